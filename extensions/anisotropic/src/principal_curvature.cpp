#include <gsp/anisotropic/principal_curvature.hpp>

#include <Eigen/Dense>

#include <cmath>

namespace gsp::anisotropic {
namespace {

Vec3 normalised(Vec3 v) {
  const double l = norm(v);
  return l > 0 ? (1 / l) * v : Vec3{0, 0, 0};
}

// Angle-weighted vertex normals: less dependent on how the one-ring is triangulated than
// area weights.
std::vector<Vec3> vertex_normals(const TriangleMesh& mesh) {
  std::vector<Vec3> n(mesh.num_vertices());
  for (const Triangle& t : mesh.triangles) {
    const Vec3 fn = normalised(cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]));
    for (int i = 0; i < 3; ++i) {
      const Vec3 a = mesh.positions[t[(i + 1) % 3]] - mesh.positions[t[i]];
      const Vec3 b = mesh.positions[t[(i + 2) % 3]] - mesh.positions[t[i]];
      n[t[i]] = n[t[i]] + std::atan2(norm(cross(a, b)), dot(a, b)) * fn;
    }
  }
  for (Vec3& v : n) v = normalised(v);
  return n;
}

void tangent_basis(Vec3 n, Vec3& t1, Vec3& t2) {
  const Vec3 axis = std::abs(n.x) < 0.6 ? Vec3{1, 0, 0} : (std::abs(n.y) < 0.6 ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  t1 = normalised(cross(n, axis));
  t2 = cross(n, t1);
}

}  // namespace

std::vector<PrincipalCurvature> principal_curvatures(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  const std::vector<Vec3> normal = vertex_normals(mesh);
  std::vector<Vec3> t1(nv), t2(nv);
  for (std::size_t v = 0; v < nv; ++v) tangent_basis(normal[v], t1[v], t2[v]);
  // Normal equations of the fit, per vertex. Unknowns (a, b, c) of S = [a b; b c]; each
  // neighbour j gives two rows: [u1 u2 0] (a b c) = g1 and [0 u1 u2] (a b c) = g2 with u the
  // tangent offset and g the tangent normal change. Every edge is seen once from each face.
  std::vector<Eigen::Matrix3d> ata(nv, Eigen::Matrix3d::Zero());
  std::vector<Eigen::Vector3d> atb(nv, Eigen::Vector3d::Zero());
  for (const Triangle& t : mesh.triangles) {
    if (repeats_vertex(t)) continue;
    for (int i = 0; i < 3; ++i) {
      const Index v = t[i];
      for (int k = 1; k < 3; ++k) {
        const Index j = t[(i + k) % 3];
        const Vec3 e = mesh.positions[j] - mesh.positions[v];
        const Vec3 dn = normal[j] - normal[v];
        const double u1 = dot(e, t1[v]), u2 = dot(e, t2[v]);
        const double g1 = dot(dn, t1[v]), g2 = dot(dn, t2[v]);
        const Eigen::Vector3d r1(u1, u2, 0), r2(0, u1, u2);
        ata[v] += r1 * r1.transpose() + r2 * r2.transpose();
        atb[v] += g1 * r1 + g2 * r2;
      }
    }
  }
  std::vector<PrincipalCurvature> out(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    PrincipalCurvature& pc = out[v];
    pc.normal = normal[v];
    if (!(norm(normal[v]) > 0)) continue;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> conditioning;
    conditioning.computeDirect(ata[v], Eigen::EigenvaluesOnly);
    const Eigen::Vector3d ev = conditioning.eigenvalues();
    if (!(ev[2] > 0) || !(ev[0] > 1e-10 * ev[2])) continue;   // the ring spans fewer than two directions
    const Eigen::Vector3d abc = ata[v].ldlt().solve(atb[v]);
    Eigen::Matrix2d s;
    s << abc[0], abc[1], abc[1], abc[2];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(s);
    if (eig.info() != Eigen::Success || !eig.eigenvalues().allFinite()) continue;
    const int big = std::abs(eig.eigenvalues()[1]) >= std::abs(eig.eigenvalues()[0]) ? 1 : 0;
    const Eigen::Vector2d dmax = eig.eigenvectors().col(big), dmin = eig.eigenvectors().col(1 - big);
    pc.max_curvature = eig.eigenvalues()[big];
    pc.min_curvature = eig.eigenvalues()[1 - big];
    pc.max_direction = normalised(dmax[0] * t1[v] + dmax[1] * t2[v]);
    pc.min_direction = normalised(dmin[0] * t1[v] + dmin[1] * t2[v]);
    pc.valid = true;
  }
  return out;
}

}  // namespace gsp::anisotropic
