#include <gsp/anisotropic/metric_sources.hpp>

#include <gsp/errors.hpp>

#include <algorithm>
#include <cctype>
#include <string>

namespace gsp::anisotropic {
namespace {

const char* const kNames[6] = {"tensor_xx", "tensor_xy", "tensor_xz", "tensor_yy", "tensor_yz", "tensor_zz"};

bool same_name(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

const std::vector<float>* find(const io::VertexAttributes& a, const std::string& name) {
  for (const auto& [n, values] : a.scalars)
    if (same_name(n, name)) return &values;
  return nullptr;
}

}  // namespace

bool has_tensor_attributes(const io::VertexAttributes& attributes) {
  return std::any_of(std::begin(kNames), std::end(kNames), [&](const char* n) { return find(attributes, n); });
}

MetricField metric_from_attributes(const io::VertexAttributes& attributes, std::size_t num_vertices) {
  const std::vector<float>* column[6];
  for (int k = 0; k < 6; ++k) {
    column[k] = find(attributes, kNames[k]);
    if (!column[k])
      throw InvalidInput(std::string("metric: no vertex property ") + kNames[k] +
                         " (a tensor needs tensor_xx, tensor_xy, tensor_xz, tensor_yy, tensor_yz, tensor_zz)");
    if (column[k]->size() != num_vertices)
      throw InvalidInput(std::string("metric: vertex property ") + kNames[k] + " has " +
                         std::to_string(column[k]->size()) + " values for " + std::to_string(num_vertices) + " vertices");
  }
  MetricField field{MetricLocation::per_vertex, std::vector<SymmetricTensor>(num_vertices)};
  for (std::size_t v = 0; v < num_vertices; ++v)
    field.tensors[v] = {(*column[0])[v], (*column[1])[v], (*column[2])[v],
                        (*column[3])[v], (*column[4])[v], (*column[5])[v]};
  return field;
}

}  // namespace gsp::anisotropic
