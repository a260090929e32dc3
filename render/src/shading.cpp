#include "shading.hpp"

#include "embree_scene.hpp"

#include <gsp/io/colormap.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gsp::render::detail {

namespace {

// Smooth normals, area-weighted (the unnormalised cross product weighs by area). Faces are
// turned to agree with the first face seen at each vertex, so an inconsistently oriented
// neighbour adds to the normal instead of cancelling it.
std::vector<float> vertex_normals(const TriangleMesh& m) {
  const std::size_t nv = m.num_vertices();
  std::vector<double> acc(3 * nv, 0.0);
  for (const Triangle& t : m.triangles) {
    const Vec3 n = cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
    for (Index v : t) {
      double* a = &acc[3 * std::size_t(v)];
      const double s = (a[0] * n.x + a[1] * n.y + a[2] * n.z) < 0.0 ? -1.0 : 1.0;
      a[0] += s * n.x;
      a[1] += s * n.y;
      a[2] += s * n.z;
    }
  }
  std::vector<float> out(3 * nv, 0.0f);
  for (std::size_t v = 0; v < nv; ++v) {
    const double l = std::sqrt(acc[3 * v] * acc[3 * v] + acc[3 * v + 1] * acc[3 * v + 1] + acc[3 * v + 2] * acc[3 * v + 2]);
    if (l > 0.0)
      for (int k = 0; k < 3; ++k) out[3 * v + k] = float(acc[3 * v + k] / l);
  }
  return out;
}

Color to_color(Rgba c) { return {float(c[0]), float(c[1]), float(c[2]), float(c[3])}; }

Color scaled(Color c, double s) {
  for (int k = 0; k < 3; ++k) c[k] = float(c[k] * s);
  return c;
}

double headlight(const Vec3& n, const Vec3& dir, double ambient) {
  const double ln = norm(n) * norm(dir);
  const double cosine = ln > 0.0 ? std::abs(dot(n, dir)) / ln : 1.0;
  return ambient + (1.0 - ambient) * std::min(cosine, 1.0);
}

// How much of a pixel a line of `width` pixels covers at `distance` pixels from its centre
// (a box filter): 1 on the line, 0 beyond half a pixel past its edge.
double coverage(double distance, double width) {
  return std::clamp(0.5 * width + 0.5 - distance, 0.0, 1.0);
}

// Change per output pixel of a function with 3D gradient g on the hit triangle's plane.
double per_pixel(const Vec3& g, const Vec3& dPdx, const Vec3& dPdy) {
  const double a = dot(g, dPdx), b = dot(g, dPdy);
  return std::sqrt(a * a + b * b);
}

Color shade_mesh(const ShadingSetup& s, const RayHit& hit) {
  const Scene& scene = *s.scene;
  const RenderOptions& o = *s.options;
  const Triangle& tri = scene.mesh.triangles[hit.primitive];
  const Vec3 p0 = scene.mesh.positions[tri[0]], p1 = scene.mesh.positions[tri[1]], p2 = scene.mesh.positions[tri[2]];
  const Vec3 e1 = p1 - p0, e2 = p2 - p0;
  Vec3 ng = cross(e1, e2);
  const double n2 = dot(ng, ng);
  const double w1 = hit.u, w2 = hit.v, w0 = 1.0 - w1 - w2;

  // Base colour: labels, else the field, else the plain surface. The field's iso-lines are
  // drawn over labels too (Voronoi regions with distance lines).
  Color c = to_color(o.surface_color);
  bool finite_field = false;
  double value = 0.0;
  if (s.has_field) {
    const double f0 = scene.vertex_field[tri[0]], f1 = scene.vertex_field[tri[1]], f2 = scene.vertex_field[tri[2]];
    finite_field = std::isfinite(f0) && std::isfinite(f1) && std::isfinite(f2);
    if (finite_field) {
      value = w0 * f0 + w1 * f1 + w2 * f2;
      c = to_color(io::colormap(o.colormap, (value - s.lo) / (s.hi - s.lo)));
    } else {
      c = to_color(o.unreached_color);
    }
  }
  if (!scene.face_labels.empty() && scene.face_labels[hit.primitive] >= 0)
    c = to_color(label_color(scene.face_labels[hit.primitive]));

  // Ray differentials on the triangle's plane: dP/dx = t (dx - d (n.dx) / (n.d)).
  const double nd = dot(ng, hit.direction);
  const bool lines = n2 > 0.0 && std::abs(nd) > 1e-12 * std::sqrt(n2) * norm(hit.direction);
  Vec3 dPdx, dPdy;
  if (lines) {
    dPdx = hit.t * (s.pixel_dx - (dot(ng, s.pixel_dx) / nd) * hit.direction);
    dPdy = hit.t * (s.pixel_dy - (dot(ng, s.pixel_dy) / nd) * hit.direction);
  }

  if (lines && finite_field && s.step > 0.0) {
    const double f0 = scene.vertex_field[tri[0]], f1 = scene.vertex_field[tri[1]], f2 = scene.vertex_field[tri[2]];
    // Gradient of the linear interpolant: grad = ((f1-f0) (e2 x n) + (f2-f0) (n x e1)) / |n|^2.
    const Vec3 grad = (1.0 / n2) * ((f1 - f0) * cross(e2, ng) + (f2 - f0) * cross(ng, e1));
    const double g = per_pixel(grad, dPdx, dPdy);   // field units per pixel
    if (g > 0.0) {
      const double levels = (value - s.lo) / s.step;
      const double k = std::round(levels);
      if (k >= 1.0 && k <= double(o.iso_lines - 1)) {
        const double spacing_px = s.step / g;
        // Where lines come closer than ~4 px they would merge into a dark band: fade them.
        const double fade = std::clamp((spacing_px - 2.0) / 2.0, 0.0, 1.0);
        const double a = fade * coverage(std::abs(levels - k) * spacing_px, o.line_width);
        c = scaled(c, 1.0 - 0.75 * a);
      }
    }
  }

  if (lines && o.wireframe) {
    // Barycentric coordinate i is 0 on the edge opposite corner i; its gradient gives the
    // distance to that edge in pixels.
    const Vec3 g1 = (1.0 / n2) * cross(e2, ng), g2 = (1.0 / n2) * cross(ng, e1);
    const Vec3 g0 = -1.0 * (g1 + g2);
    const double w[3] = {w0, w1, w2};
    const Vec3 g[3] = {g0, g1, g2};
    double nearest = std::numeric_limits<double>::infinity(), smallest_height = nearest;
    for (int i = 0; i < 3; ++i) {
      const double d = per_pixel(g[i], dPdx, dPdy);   // 1 / (triangle height in pixels)
      if (d > 0.0) {
        nearest = std::min(nearest, std::max(w[i], 0.0) / d);
        smallest_height = std::min(smallest_height, 1.0 / d);
      }
    }
    // Triangles a few pixels tall would turn black under their edges: fade to a hint.
    const double strength = 0.65 * std::clamp((smallest_height - 2.0) / 6.0, 0.2, 1.0);
    c = scaled(c, 1.0 - strength * coverage(nearest, o.line_width));
  }

  // Smooth normal, unless it strays far from the face (a crease the mesh does not split).
  Vec3 n = ng;
  if (!s.normals.empty()) {
    auto vn = [&](Index v) {
      const float* p = &s.normals[3 * std::size_t(v)];
      return Vec3{p[0], p[1], p[2]};
    };
    Vec3 smooth = w0 * vn(tri[0]) + w1 * vn(tri[1]) + w2 * vn(tri[2]);
    if (dot(smooth, ng) < 0.0) smooth = -1.0 * smooth;
    const double ls = norm(smooth), lg = std::sqrt(n2);
    if (ls > 1e-6 && lg > 0.0 && dot(smooth, ng) > 0.7 * ls * lg) n = smooth;   // within ~45 degrees
  }
  return scaled(c, headlight(n, hit.direction, o.ambient));
}

}  // namespace

ShadingSetup prepare_shading(const Scene& scene, const RenderOptions& options, Vec3 pixel_dx, Vec3 pixel_dy) {
  ShadingSetup s;
  s.scene = &scene;
  s.options = &options;
  s.pixel_dx = pixel_dx;
  s.pixel_dy = pixel_dy;
  if (!scene.mesh.triangles.empty()) s.normals = vertex_normals(scene.mesh);
  s.has_field = !scene.vertex_field.empty();
  if (s.has_field) {
    double lo = options.range_lo, hi = options.range_hi;
    if (!(hi > lo)) {
      lo = std::numeric_limits<double>::infinity();
      hi = -lo;
      for (double v : scene.vertex_field)
        if (std::isfinite(v)) {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
      if (!(hi >= lo)) lo = hi = 0.0;   // nothing reached
    }
    if (!(hi > lo)) hi = lo + 1.0;      // a constant field: one colour, no lines
    s.lo = lo;
    s.hi = hi;
    if (options.iso_lines > 0) s.step = (hi - lo) / options.iso_lines;
  }
  return s;
}

Color shade(const ShadingSetup& s, const RayHit& hit) {
  const RenderOptions& o = *s.options;
  switch (hit.geometry) {
    case kMeshGeometry: return shade_mesh(s, hit);
    case kPointGeometry: return scaled(to_color(o.point_color), headlight(hit.normal, hit.direction, o.ambient));
    case kLineGeometry: return scaled(to_color(o.line_color), headlight(hit.normal, hit.direction, o.ambient));
    case kSourceGeometry: return scaled(to_color(o.source_color), headlight(hit.normal, hit.direction, o.ambient));
    default: return to_color(o.background);
  }
}

Rgba label_color(std::int32_t label) {
  // HSV with golden-ratio hue steps, two saturation/value rows so that 1.6 apart is not twins.
  const double h = std::fmod(0.11 + 0.6180339887498949 * double(label), 1.0) * 6.0;
  const double sat = (label % 2) ? 0.45 : 0.65, val = (label % 3 == 1) ? 0.8 : 0.95;
  const int sector = int(h) % 6;
  const double f = h - std::floor(h);
  const double p = val * (1 - sat), q = val * (1 - sat * f), t = val * (1 - sat * (1 - f));
  double r = val, g = t, b = p;
  switch (sector) {
    case 0: r = val, g = t, b = p; break;
    case 1: r = q, g = val, b = p; break;
    case 2: r = p, g = val, b = t; break;
    case 3: r = p, g = q, b = val; break;
    case 4: r = t, g = p, b = val; break;
    default: r = val, g = p, b = q; break;
  }
  return {std::uint8_t(std::lround(255 * r)), std::uint8_t(std::lround(255 * g)), std::uint8_t(std::lround(255 * b)),
          255};
}

}  // namespace gsp::render::detail
