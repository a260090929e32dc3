#pragma once
// Shared by the fuzz targets: the input bytes become a file with the format's extension (the
// readers choose by extension), read_mesh reads it, and anything but a clean result or a
// gsp::Error is a bug: a sanitizer report, another exception, or a result that breaks the
// documented invariants (indices in range, finite positions, per-vertex arrays sized right).
// Each input is also read by the parallel text parsers (three threads, whatever its size), and
// the two reads must agree: the same mesh and attributes, or the same error message.
#include <gsp/io/mesh_io.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

// Bit for bit: a file may hold NaN scalars.
inline bool same_scalars(const std::vector<std::pair<std::string, std::vector<float>>>& a,
                         const std::vector<std::pair<std::string, std::vector<float>>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].first != b[i].first || a[i].second.size() != b[i].second.size() ||
        (!a[i].second.empty() && std::memcmp(a[i].second.data(), b[i].second.data(), a[i].second.size() * sizeof(float)) != 0))
      return false;
  return true;
}

inline bool same_read(const io::ReadResult& a, const io::ReadResult& b) {
  auto bits = [](const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(Vec3)) == 0);
  };
  return a.mesh.triangles == b.mesh.triangles && bits(a.mesh.positions, b.mesh.positions) &&
         bits(a.mesh.normals, b.mesh.normals) && a.attributes.colors == b.attributes.colors &&
         a.attributes.labels == b.attributes.labels && a.info.file_vertices == b.info.file_vertices &&
         a.info.file_faces == b.info.file_faces && a.info.polygons_split == b.info.polygons_split &&
         a.info.notes == b.info.notes && same_scalars(a.attributes.scalars, b.attributes.scalars);
}

// The serial and the parallel parsers agree on `path`.
inline void check_parallel_agrees(const std::string& path, const io::ReadResult* serial, const std::string& error) {
  io::ReadOptions parallel;
  parallel.threads = 3;
  parallel.parallel_from_bytes = 0;
  try {
    const io::ReadResult r = io::read_mesh(path, parallel);
    check(serial && same_read(*serial, r), "the parallel parser read what the serial one did not, or differently");
  } catch (const gsp::Error& e) {
    check(!serial && error == e.what(), "the parallel parser failed where the serial one did not, or differently");
  }
}

inline int read_as(const char* ext, const std::uint8_t* data, std::size_t size) {
  static const std::string path = scratch_path(ext);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  try {
    io::ReadOptions serial;
    serial.threads = 1;
    const io::ReadResult r = io::read_mesh(path, serial);
    const std::size_t n = r.mesh.num_vertices();
    for (const Triangle& t : r.mesh.triangles)
      for (Index v : t) check(v < n, "triangle index out of range");
    for (const Vec3& p : r.mesh.positions) check(is_finite(p), "non-finite position");
    check(r.mesh.normals.empty() || r.mesh.normals.size() == n, "normals not one per vertex");
    for (const auto& s : r.attributes.scalars) check(s.second.size() == n, "scalar attribute size");
    for (const auto& l : r.attributes.labels) check(l.second.size() == n, "label attribute size");
    check(r.attributes.colors.empty() || r.attributes.colors.size() == n, "colour count");
    check_parallel_agrees(path, &r, "");
  } catch (const gsp::Error& e) {
    // Rejected cleanly: what the readers promise for bad input.
    check_parallel_agrees(path, nullptr, e.what());
  }
  return 0;
}

}  // namespace gsp::fuzz
