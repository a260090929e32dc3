#include "write_samples.hpp"

#include <gsp/io/atomic_file.hpp>
#include <gsp/io/mesh_io.hpp>

#include <cstdio>

namespace gsp::sample_app {

namespace {

void write_txt(const std::string& path, const std::vector<sampling::Sample>& samples) {
  io::AtomicFile file(path);
  std::string text;
  char line[256];
  for (const sampling::Sample& s : samples) {
    const int n = std::snprintf(line, sizeof line, "%.9g %.9g %.9g %.7g %.7g %.7g %u %.9g %.9g\n",
                                s.position.x, s.position.y, s.position.z, s.normal.x, s.normal.y,
                                s.normal.z, unsigned(s.point.element), s.point.barycentric[1], s.point.barycentric[2]);
    text.append(line, std::size_t(n));
  }
  file.write(text.data(), text.size());
  file.commit();
}

}  // namespace

void write_samples(const std::string& path, const std::vector<sampling::Sample>& samples, bool ascii) {
  if (io::format_from_path(path) == io::Format::txt) return write_txt(path, samples);
  TriangleMesh cloud;
  io::VertexAttributes attributes;
  std::vector<std::int32_t> face;
  std::vector<float> u, v;
  for (const sampling::Sample& s : samples) {
    cloud.positions.push_back(s.position);
    cloud.normals.push_back(s.normal);
    face.push_back(std::int32_t(s.point.element));
    u.push_back(float(s.point.barycentric[1]));
    v.push_back(float(s.point.barycentric[2]));
  }
  attributes.labels.emplace_back("face", std::move(face));
  attributes.scalars.emplace_back("u", std::move(u));
  attributes.scalars.emplace_back("v", std::move(v));
  io::WriteOptions options;
  options.ascii = ascii;
  io::write_mesh(path, cloud, attributes, options);
}

}  // namespace gsp::sample_app
