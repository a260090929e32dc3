#pragma once
// What a path traced back through a field reads from it: per face, the straight line the
// geodesic into a point comes along (a virtual source S in the face's plane and the length
// sigma left there), and the vertex distances for the descent route. GSP's field has one
// source per face (GeodesicResult::face_sources); a window field (gsp/window_geodesics.hpp)
// has a few and picks the one that explains the point, so the walk follows the corridor the
// point's own geodesic takes.
#include <gsp/geodesics.hpp>
#include <gsp/window_geodesics.hpp>

#include <array>
#include <vector>

namespace gsp::pathfinding::detail {

class SourceField {
 public:
  virtual ~SourceField() = default;
  virtual bool reached(Index face) const = 0;
  // The source the geodesic into point x of `face` heads for.
  virtual VirtualSource source_at(Index face, Vec3 x) const = 0;
  virtual const std::vector<double>& vertex_distance() const = 0;
  virtual const std::vector<Index>& vertex_source() const = 0;
  virtual double distance_at(const TriangleMesh& mesh, Index face, const std::array<double, 3>& bary) const = 0;
};

// GSP's field: one source per face, whatever the point.
class GspSourceField final : public SourceField {
 public:
  explicit GspSourceField(const GeodesicResult& field) : field_(field) {}
  bool reached(Index face) const override { return face < field_.face_sources.size() && field_.face_sources[face].reached(); }
  VirtualSource source_at(Index face, Vec3) const override { return field_.face_sources[face]; }
  const std::vector<double>& vertex_distance() const override { return field_.vertex_distance; }
  const std::vector<Index>& vertex_source() const override { return field_.vertex_source; }
  double distance_at(const TriangleMesh& mesh, Index face, const std::array<double, 3>& bary) const override {
    return field_.distance_at(mesh, face, bary);
  }

 private:
  const GeodesicResult& field_;
};

// A window field on the input's faces.
class WindowSourceField final : public SourceField {
 public:
  explicit WindowSourceField(const WindowField& field) : field_(field) {}
  bool reached(Index face) const override { return field_.reached(face); }
  VirtualSource source_at(Index face, Vec3 x) const override { return field_.source_at(face, x); }
  const std::vector<double>& vertex_distance() const override { return field_.vertex_distance; }
  const std::vector<Index>& vertex_source() const override { return field_.vertex_source; }
  double distance_at(const TriangleMesh&, Index face, const std::array<double, 3>& bary) const override {
    return field_.distance_at(face, bary);
  }

 private:
  const WindowField& field_;
};

}  // namespace gsp::pathfinding::detail
