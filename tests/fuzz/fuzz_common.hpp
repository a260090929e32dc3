#pragma once
// Shared by the fuzz targets: the input bytes become a file with the format's extension (the
// readers choose by extension), read_mesh reads it, and anything but a clean result or a
// gsp::Error is a bug: a sanitizer report, another exception, or a result that breaks the
// documented invariants (indices in range, finite positions, per-vertex arrays sized right).
#include <gsp/io/mesh_io.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

namespace gsp::fuzz {

// A private folder (glTF URIs resolve inside it), in memory when /dev/shm exists: rewriting a
// file on disk for every input costs ~4 ms here, 100 times the read itself.
inline std::string scratch_path(const char* ext) {
  const char* base = std::getenv("GSP_FUZZ_TMP");
  std::string templ = std::string(base ? base : (::access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp")) + "/gsp-fuzz-XXXXXX";
  if (!::mkdtemp(&templ[0])) std::abort();
  return templ + "/input" + ext;
}

inline void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "invariant broken: %s\n", what);
    std::abort();
  }
}

inline int read_as(const char* ext, const std::uint8_t* data, std::size_t size) {
  static const std::string path = scratch_path(ext);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  try {
    const io::ReadResult r = io::read_mesh(path);
    const std::size_t n = r.mesh.num_vertices();
    for (const Triangle& t : r.mesh.triangles)
      for (Index v : t) check(v < n, "triangle index out of range");
    for (const Vec3& p : r.mesh.positions) check(is_finite(p), "non-finite position");
    check(r.mesh.normals.empty() || r.mesh.normals.size() == n, "normals not one per vertex");
    for (const auto& s : r.attributes.scalars) check(s.second.size() == n, "scalar attribute size");
    for (const auto& l : r.attributes.labels) check(l.second.size() == n, "label attribute size");
    check(r.attributes.colors.empty() || r.attributes.colors.size() == n, "colour count");
  } catch (const gsp::Error&) {
    // Rejected cleanly: what the readers promise for bad input.
  }
  return 0;
}

}  // namespace gsp::fuzz
