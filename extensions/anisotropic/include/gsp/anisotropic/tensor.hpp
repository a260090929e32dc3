#pragma once
// A symmetric 3x3 tensor: the Riemannian metric of a face or vertex. The length of a step e
// (a 3D vector in the surface) is sqrt(e^T M e); M = identity is the ordinary 3D length.
#include <gsp/types.hpp>

namespace gsp::anisotropic {

struct SymmetricTensor {
  double xx = 1, xy = 0, xz = 0, yy = 1, yz = 0, zz = 1;   // default: the identity

  static SymmetricTensor identity() { return {}; }
  static SymmetricTensor diagonal(double a, double b, double c) { return {a, 0, 0, b, 0, c}; }
  // I + (ratio^2 - 1) d d^T for a unit vector d: a unit step along d costs `ratio`, a unit
  // step across it costs 1. ratio == 1 gives exactly the identity.
  static SymmetricTensor stretch(Vec3 unit_direction, double ratio);

  // e^T (M - I) e: what the metric adds to |e|^2. Exactly 0 when M is the identity, so
  // sqrt(dot(e, e) + excess(e)) is then bit for bit the 3D length.
  double excess(Vec3 e) const;
  // e^T M e.
  double quadratic(Vec3 e) const { return dot(e, e) + excess(e); }
  // All six entries finite and M positive definite (Sylvester's leading minors, scaled).
  bool is_positive_definite() const;
  // The smallest eigenvalue: every step e costs at least sqrt(it) |e| in this metric.
  double smallest_eigenvalue() const;
};

SymmetricTensor operator+(const SymmetricTensor& a, const SymmetricTensor& b);
SymmetricTensor operator*(double s, const SymmetricTensor& a);

}  // namespace gsp::anisotropic
