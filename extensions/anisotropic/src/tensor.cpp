#include <gsp/anisotropic/tensor.hpp>

#include <Eigen/Eigenvalues>

#include <cmath>

namespace gsp::anisotropic {

SymmetricTensor SymmetricTensor::stretch(Vec3 d, double ratio) {
  const double k = ratio * ratio - 1;   // exactly 0 for ratio 1: the identity, bit for bit
  return {1 + k * d.x * d.x, k * d.x * d.y, k * d.x * d.z, 1 + k * d.y * d.y, k * d.y * d.z, 1 + k * d.z * d.z};
}

double SymmetricTensor::excess(Vec3 e) const {
  // Diagonal entries minus one, so the identity contributes exact zeros (not 1*x*x - x*x).
  return (xx - 1) * e.x * e.x + (yy - 1) * e.y * e.y + (zz - 1) * e.z * e.z +
         2 * (xy * e.x * e.y + xz * e.x * e.z + yz * e.y * e.z);
}

bool SymmetricTensor::is_positive_definite() const {
  for (double v : {xx, xy, xz, yy, yz, zz})
    if (!std::isfinite(v)) return false;
  Eigen::Matrix3d m;
  m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues();
  // Relative: a tensor with condition number beyond 1e12 is singular for every practical purpose.
  return eig[0] > 1e-12 * eig[2] && eig[2] > 0;
}

double SymmetricTensor::smallest_eigenvalue() const {
  Eigen::Matrix3d m;
  m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues()[0];
}

SymmetricTensor operator+(const SymmetricTensor& a, const SymmetricTensor& b) {
  return {a.xx + b.xx, a.xy + b.xy, a.xz + b.xz, a.yy + b.yy, a.yz + b.yz, a.zz + b.zz};
}

SymmetricTensor operator*(double s, const SymmetricTensor& a) {
  return {s * a.xx, s * a.xy, s * a.xz, s * a.yy, s * a.yz, s * a.zz};
}

}  // namespace gsp::anisotropic
