#pragma once
// Carried windows (docs/gsp-core.md, rule 10): per face, up to two vertices that bound what the
// face's virtual source sees, carried along straight steps, so that a straight step whose line
// of sight has passed such a vertex on its hidden side bends there instead. Internal header of
// libgsp; UpdateStep (update_step.hpp) asks these functions, window_corners.hpp says which
// vertices bound.
//
// Why: a source carried round a hole in a planar CAD region one face at a time passes every
// step's local test (its probe sees it through the shared edge), though its line crossed the
// hole a few faces back. A face remembers the rim vertices its source's line passed (the
// window's sides) and the next face's probe is held against them.
#include <gsp/types.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <utility>

namespace gsp::detail {

// Two bounding vertices in some 2D frame (a face's canonical frame or an edge frame). Slot 0:
// a point Q is seen only where (W0 - S) x (Q - S) >= 0 for the source S; slot 1: where
// (W1 - S) x (Q - S) <= 0. A NaN x: no bound in that slot.
struct WindowSides {
  float x[2], y[2];
  static WindowSides none() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return {{nan, nan}, {nan, nan}};
  }
  bool has(int k) const { return x[k] == x[k]; }
  bool any() const { return has(0) || has(1); }
};

// What a face keeps: its sides in its canonical frame and the face's dT when they were written.
// A record whose dT differs was updated or seeded since without a window: its sides are stale.
// All zero (`written` false): nothing written.
template <class Real>
struct WindowRecord {
  WindowSides sides;
  Real stamp;
  bool written;
  bool holds(Real dT) const { return written && stamp == dT; }
};

// A query's window records, one per face, zeroed by calloc: a large block comes as fresh pages
// the kernel zeroes when first touched, so a query pays only for the pages of the faces that
// hold a window (a scan with a few coplanar faces: a few pages), not a fill of the whole mesh.
template <class Real>
class WindowStore {
 public:
  WindowStore() = default;
  explicit WindowStore(std::size_t faces)
      : records_(static_cast<WindowRecord<Real>*>(std::calloc(faces == 0 ? 1 : faces, sizeof(WindowRecord<Real>)))) {
    if (!records_) throw std::bad_alloc();
  }
  WindowRecord<Real>* get() const { return records_.get(); }
  explicit operator bool() const { return bool(records_); }

 private:
  struct Free {
    void operator()(WindowRecord<Real>* p) const { std::free(p); }
  };
  std::unique_ptr<WindowRecord<Real>[], Free> records_;
};

// The constants, measured on the corpus (docs/gsp-core.md, rule 10).
// A bound closer to the source than this many lengths of the crossed edge is not kept: the
// half-plane through the source and a point next to it is rounding noise.
inline constexpr double kWindowNearSource = 0.1;
// A probe at this lambda (from the opposite corner towards the centroid) that still sees the
// source keeps the step straight: the table's probe sits almost at the opposite corner of
// needles, and the window then bends for a sliver of the face.
inline constexpr double kWindowLooseLambda = 0.15;
// Bends only into faces of aspect (longest edge squared over twice the area) below this: a
// window bend taken for a long sliver near one end bends all of it.
inline constexpr double kWindowMaxAspect = 10;
// Bends only between faces in one plane (intrinsic::coplanar_across, gsp/intrinsic/coplanar_faces.hpp):
// in a planar region a bend at a hiding rim vertex is the true path; on curved surfaces GSP's
// straight values below exact and bent ones above cancel, and the window would take the bent side.

// Sides given in the sending face's edge frame (hx, hy: U on +y) unfolded into the receiving
// face's edge frame the way unfold() moves the source: y flips; x is mirrored unless the faces
// walk the edge the same way. One reflection (same direction) swaps the slots' senses.
inline WindowSides unfold_sides(const WindowSides& s, bool same_dir, float e1h) {
  WindowSides r;
  for (int k = 0; k < 2; ++k) {
    const int to = same_dir ? 1 - k : k;
    r.x[to] = same_dir ? s.x[k] : e1h - s.x[k];
    r.y[to] = -s.y[k];
  }
  return r;
}

// Which side (0 or 1) a window bound W at (wx, wy) takes for a source (sx, sy) so that the
// point (ox, oy) is on its seen side; -1 where the three are collinear (no side).
template <class Real>
inline int side_towards(Real wx, Real wy, Real sx, Real sy, Real ox, Real oy) {
  const Real c = (wx - sx) * (oy - sy) - (wy - sy) * (ox - sx);
  return c > 0 ? 0 : (c < 0 ? 1 : -1);
}

// Adds bound W to slot k, keeping the tighter of two (the one whose seen side lies within the
// other's).
template <class Real>
inline void tighten(WindowSides& s, int k, Real wx, Real wy, Real sx, Real sy) {
  if (s.has(k)) {
    const Real c = (Real(s.x[k]) - sx) * (wy - sy) - (Real(s.y[k]) - sy) * (wx - sx);
    if (!(k == 0 ? c > 0 : c < 0)) return;
  }
  s.x[k] = float(wx), s.y[k] = float(wy);
}

// The bound (0 or 1) whose hidden side the line from the source S to the probe Q lies on,
// while a probe L nearer the centroid does not see S either; -1 for none. Both in the
// receiving face's edge frame.
template <class Real>
inline int hidden_by(const WindowSides& s, Real sx, Real sy, Real qx, Real qy, Real lx, Real ly, Real e1) {
  const Real near = Real(kWindowNearSource) * e1;
  for (int k = 0; k < 2; ++k) {
    if (!s.has(k)) continue;
    const Real ax = Real(s.x[k]) - sx, ay = Real(s.y[k]) - sy;
    const Real a2 = ax * ax + ay * ay;
    if (a2 <= near * near) continue;
    const Real sign = k == 0 ? Real(1) : Real(-1);
    const Real bx = qx - sx, by = qy - sy;
    const Real tol = Real(1e-5) * std::sqrt(a2 * (bx * bx + by * by));
    if (!(sign * (ax * by - ay * bx) < -tol)) continue;
    const Real mx = lx - sx, my = ly - sy;
    if (sign * (ax * my - ay * mx) < -tol) return k;
  }
  return -1;
}

}  // namespace gsp::detail
