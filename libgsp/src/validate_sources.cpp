#include "validate_sources.hpp"

#include "face_record.hpp"

#include <gsp/errors.hpp>
#include <gsp/surface_point.hpp>

#include <cmath>
#include <string>

namespace gsp::detail {

void validate_sources(const std::vector<Source>& sources, const TriangleMesh& mesh) {
  if (sources.size() >= kNoSource) throw InvalidInput("too many sources (at most 2^26 - 1)");
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const Source& src = sources[s];
    if (!std::isfinite(src.offset) || src.offset < 0)
      throw InvalidInput("source " + std::to_string(s) + ": offset must be finite and >= 0");
    if (!src.exists_in(mesh)) throw InvalidInput("source " + src.missing_from(mesh));
    if (!src.is_vertex() && !are_barycentric(src.barycentric))
      throw InvalidInput("source " + std::to_string(s) + ": barycentric coordinates must be >= 0 and sum to 1");
  }
}

}  // namespace gsp::detail
