// The CVT energy from one multi-source propagation: per face, the integral of the squared
// distance to the face's virtual source.
#include <gsp/cvt/cvt.hpp>
#include <gsp/errors.hpp>

#include <cmath>

namespace gsp::cvt {

double cvt_energy(const TriangleMesh& mesh, const GeodesicResult& result) {
  if (result.face_sources.size() != mesh.num_faces())
    throw InvalidInput("cvt_energy: the result has no per-face virtual sources (want_face_sources)");
  double energy = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const VirtualSource& s = result.face_sources[f];
    if (!s.reached()) continue;
    const Triangle& t = mesh.triangles[f];
    const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const double area = 0.5 * norm(cross(b - a, c - a));
    if (!(area > 0)) continue;
    // Edge-midpoint rule: exact for polynomials of degree 2 over a triangle; (sigma + |p-S|)^2
    // is smooth inside a face, so this is close without needing more evaluations.
    double sum = 0;
    for (const Vec3& m : {0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)}) {
      const double d = s.sigma + distance(m, s.position);
      sum += d * d;
    }
    energy += area * sum / 3.0;
  }
  return energy;
}

}  // namespace gsp::cvt
