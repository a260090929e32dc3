// Normals by local PCA (Eigen's SelfAdjointEigenSolver on the 3x3 covariance of the k nearest
// points), tangents by a branch-free orthonormal basis, the curvature sign by a least-squares
// quadric over the tangent plane.
#include "tangent_frames.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace gsp::pointcloud::detail {
namespace {

// Unit normal of the neighbourhood, or +z where it has no extent (a lone point, all duplicates).
Vec3 pca_normal(const std::vector<Vec3>& points, const Index* idx, std::size_t count) {
  if (count < 3) return {0, 0, 1};
  Vec3 mean;
  for (std::size_t a = 0; a < count; ++a) mean = mean + points[idx[a]];
  mean = (1.0 / static_cast<double>(count)) * mean;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t a = 0; a < count; ++a) {
    const Vec3 d = points[idx[a]] - mean;
    const Eigen::Vector3d v(d.x, d.y, d.z);
    cov += v * v.transpose();
  }
  if (!(cov.trace() > 0)) return {0, 0, 1};
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  if (eig.info() != Eigen::Success) return {0, 0, 1};
  const Eigen::Vector3d n = eig.eigenvectors().col(0);   // smallest eigenvalue first
  const Vec3 out{n.x(), n.y(), n.z()};
  const double len = norm(out);
  return (len > 0 && std::isfinite(len)) ? (1.0 / len) * out : Vec3{0, 0, 1};
}

// Duff et al. 2017, "Building an orthonormal basis, revisited".
void tangents(Vec3 n, Vec3& b1, Vec3& b2) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  b1 = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  b2 = {b, sign + n.y * n.y * a, -n.y};
}

// Whether the surface through `self` is elliptic there (Gaussian curvature > 0): the height
// over the tangent plane fitted as z = a x^2 + b xy + c y^2 + d x + e y (least squares over the
// neighbours; the linear terms absorb a tilted normal), K ~ 4ac - b^2. Its sign does not
// depend on the normal's orientation. Fewer than 6 neighbours: not elliptic.
bool elliptic_at(const std::vector<Vec3>& points, Index self, const Index* idx, std::size_t count, Vec3 n, Vec3 t1,
                 Vec3 t2) {
  Eigen::Matrix<double, Eigen::Dynamic, 5> A(count, 5);
  Eigen::VectorXd z(count);
  Eigen::Index rows = 0;
  for (std::size_t a = 0; a < count; ++a) {
    if (idx[a] == self) continue;
    const Vec3 d = points[idx[a]] - points[self];
    const double x = dot(d, t1), y = dot(d, t2);
    A.row(rows) << x * x, x * y, y * y, x, y;
    z(rows++) = dot(d, n);
  }
  if (rows < 6) return false;
  const Eigen::Matrix<double, 5, 1> c = A.topRows(rows).colPivHouseholderQr().solve(z.head(rows));
  return 4 * c(0) * c(2) - c(1) * c(1) > 0;
}

}  // namespace

TangentFrames tangent_frames(const std::vector<Vec3>& points, const std::vector<Vec3>& input_normals,
                             const PointTree& tree, unsigned k) {
  const std::size_t n = points.size();
  TangentFrames f;
  f.normal.resize(n);
  f.t1.resize(n);
  f.t2.resize(n);
  f.elliptic.assign(n, 0);
  const std::size_t want = std::max<std::size_t>(k, 3) + 1;   // the point itself comes back too
  std::vector<Index> idx(want);
  std::vector<double> d2(want);
  for (Index i = 0; i < n; ++i) {
    Vec3 nn{0, 0, 0};
    if (!input_normals.empty()) {
      const Vec3 given = input_normals[i];
      const double len = norm(given);
      if (is_finite(given) && len > 0) nn = (1.0 / len) * given;
    }
    const std::size_t got = tree.knn(points[i], want, idx.data(), d2.data());
    if (nn == Vec3{0, 0, 0}) {
      nn = pca_normal(points, idx.data(), got);
      ++f.estimated;
    } else {
      ++f.from_input;
    }
    f.normal[i] = nn;
    tangents(nn, f.t1[i], f.t2[i]);
    f.elliptic[i] = elliptic_at(points, i, idx.data(), got, nn, f.t1[i], f.t2[i]);
  }
  return f;
}

}  // namespace gsp::pointcloud::detail
