#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/errors.hpp>

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace gsp::cvt {

struct ClosestPointIndex::Impl {
  const TriangleMesh& mesh;
  std::vector<Index> faces;   // Embree primitive -> mesh face
  Vec3 origin;                // positions are stored as floats relative to it
  double slack = 0;           // the float boxes' rounding, bounded: a few ulps of the largest coordinate
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;

  explicit Impl(const TriangleMesh& m) : mesh(m) {}
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

struct Query {
  const ClosestPointIndex* self;
  const TriangleMesh* mesh;
  const std::vector<Index>* faces;
  Vec3 p;
  ClosestPoint best;
  double slack;
};

// Where on face f the closest point to p lies, and how far.
ClosestPoint face_point(const TriangleMesh& mesh, Index f, Vec3 p) {
  const Triangle& t = mesh.triangles[f];
  const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
  const std::array<double, 3> w = closest_point_on_triangle(p, a, b, c);
  ClosestPoint r;
  r.point = SurfacePoint::in_face(f, w);
  r.position = w[0] * a + w[1] * b + w[2] * c;
  r.distance = distance(r.position, p);
  return r;
}

// The search radius that keeps every face within distance d: Embree culls by float boxes
// around float positions, so d is widened by their rounding (the callbacks decide in double).
float search_radius(double d, double slack) { return float(d * (1 + 1e-5) + slack) + 1e-30f; }

bool query_triangle(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<Query*>(args->userPtr);
  const Index f = (*q->faces)[args->primID];
  const ClosestPoint r = face_point(*q->mesh, f, q->p);
  // Ties (a point on an edge is as near to both faces) go to the lower face index, so the
  // answer does not depend on the order in which the BVH, built in parallel, is walked (nor
  // on the hint the search started from): the radius keeps the tied faces' boxes in reach.
  if (r.distance > q->best.distance || (r.distance == q->best.distance && f >= q->best.point.element)) return false;
  q->best = r;
  args->query->radius = search_radius(r.distance, q->slack);
  return true;
}

struct WithinQuery {
  const TriangleMesh* mesh;
  const std::vector<Index>* faces;
  Vec3 p;
  double r;
  bool found;
  Index face;   // the one found
};

bool query_within(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<WithinQuery*>(args->userPtr);
  if (q->found) return false;
  const Index f = (*q->faces)[args->primID];
  if (!(face_point(*q->mesh, f, q->p).distance <= q->r)) return false;
  q->found = true;
  q->face = f;
  args->query->radius = 0;   // nothing more to look at
  return true;
}

}  // namespace

ClosestPointIndex::ClosestPointIndex(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>(mesh)) {
  Impl& s = *impl_;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) s.faces.push_back(f);
  }
  if (s.faces.empty()) throw InvalidInput("closest point index: the mesh has no proper triangle");
  s.origin = bounding_box(mesh).center();
  for (const Vec3& p : mesh.positions)
    s.slack = std::max({s.slack, std::abs(p.x - s.origin.x), std::abs(p.y - s.origin.y), std::abs(p.z - s.origin.z)});
  s.slack *= 8 * double(std::numeric_limits<float>::epsilon());
  s.device = rtcNewDevice(nullptr);
  if (!s.device) throw Error("closest point index: Embree could not create a device");
  s.scene = rtcNewScene(s.device);
  RTCGeometry g = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), mesh.num_vertices()));
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(unsigned), s.faces.size()));
  if (!v || !idx) {
    rtcReleaseGeometry(g);
    throw Error("closest point index: Embree could not allocate the mesh");
  }
  for (std::size_t i = 0; i < mesh.num_vertices(); ++i) {
    const Vec3 p = mesh.positions[i] - s.origin;
    v[3 * i] = float(p.x), v[3 * i + 1] = float(p.y), v[3 * i + 2] = float(p.z);
  }
  for (std::size_t i = 0; i < s.faces.size(); ++i)
    for (int k = 0; k < 3; ++k) idx[3 * i + k] = mesh.triangles[s.faces[i]][k];
  rtcCommitGeometry(g);
  rtcAttachGeometry(s.scene, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(s.scene);
  if (rtcGetDeviceError(s.device) != RTC_ERROR_NONE) throw Error("closest point index: Embree failed to build the scene");
}

ClosestPointIndex::~ClosestPointIndex() = default;

ClosestPoint ClosestPointIndex::closest(Vec3 p) const { return closest(p, kInvalidIndex); }

ClosestPoint ClosestPointIndex::on_face(Index f, Vec3 p) const { return face_point(impl_->mesh, f, p); }

ClosestPoint ClosestPointIndex::closest(Vec3 p, Index hint) const {
  const Impl& s = *impl_;
  Query q{this, &s.mesh, &s.faces, p, {}, s.slack};
  q.best.distance = std::numeric_limits<double>::infinity();
  const Vec3 local = p - s.origin;
  RTCPointQuery pq;
  pq.x = float(local.x), pq.y = float(local.y), pq.z = float(local.z);
  pq.time = 0;
  pq.radius = std::numeric_limits<float>::infinity();
  if (hint != kInvalidIndex) {
    q.best = face_point(s.mesh, hint, p);
    pq.radius = search_radius(q.best.distance, s.slack);
  }
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  // The callback reads positions in model units; Embree's boxes are in the shifted frame, and
  // a shift changes no distance.
  rtcPointQuery(s.scene, &pq, &context, query_triangle, &q);
  return q.best;
}

bool ClosestPointIndex::within(Vec3 p, double r) const {
  Index hint = kInvalidIndex;
  return within(p, r, hint);
}

bool ClosestPointIndex::within(Vec3 p, double r, Index& hint) const {
  const Impl& s = *impl_;
  if (!(r >= 0)) return false;
  if (hint != kInvalidIndex && face_point(s.mesh, hint, p).distance <= r) return true;
  WithinQuery q{&s.mesh, &s.faces, p, r, false, kInvalidIndex};
  const Vec3 local = p - s.origin;
  RTCPointQuery pq;
  pq.x = float(local.x), pq.y = float(local.y), pq.z = float(local.z);
  pq.time = 0;
  pq.radius = search_radius(r, s.slack);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(s.scene, &pq, &context, query_within, &q);
  if (q.found) hint = q.face;
  return q.found;
}

}  // namespace gsp::cvt
