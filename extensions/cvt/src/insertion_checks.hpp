#pragma once
// The rules a tried far-point insertion (a split and the flips around the new vertex) must keep,
// read off the edits since EditableMesh::begin(): it must not fold the mesh, lower its floor,
// take the chords off the surface, nor carry the input near it away from the mesh.
#include "editable_mesh.hpp"
#include "point_grid.hpp"
#include "refine.hpp"

#include <vector>

namespace gsp::cvt {
class ClosestPointIndex;
}

namespace gsp::cvt::detail {

class InsertionChecks {
 public:
  // `input`: the input's points (the surface's vertices), with their area-weighted normals and a
  // grid over them; `index`: over the input's surface.
  InsertionChecks(const EditableMesh& em, const std::vector<Vec3>& input, const std::vector<Vec3>& input_normal,
                  const PointGrid& grid, const ClosestPointIndex& index, const RefineParams& p)
      : em_(em), input_(input), input_normal_(input_normal), grid_(grid), index_(index), p_(p) {}

  // The new vertex at z, `reference`: the normal of the faces it replaced. The smallest angle of
  // the changed triangles, or -1 if they break a rule.
  double judge(Vec3 z, Vec3 reference, double floor_angle) const;

 private:
  double unfolded_min_angle(const std::vector<Index>& changed) const;
  double deviation(const Triangle& t) const;
  bool keeps_deviation(const std::vector<Index>& changed, const std::vector<Triangle>& replaced) const;
  bool keeps_input_close(Vec3 z, Vec3 reference, const std::vector<Index>& changed,
                         const std::vector<Triangle>& replaced) const;

  const EditableMesh& em_;
  const std::vector<Vec3>& input_;
  const std::vector<Vec3>& input_normal_;
  const PointGrid& grid_;
  const ClosestPointIndex& index_;
  const RefineParams& p_;
};

}  // namespace gsp::cvt::detail
