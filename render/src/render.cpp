#include <gsp/render/render.hpp>

#include "embree_scene.hpp"
#include "shading.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

namespace gsp::render {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

detail::Radii radii_for(const Scene& s, double scene_radius) {
  detail::Radii r;
  r.point = s.point_radius > 0.0 ? s.point_radius : 0.008 * scene_radius;
  r.line = s.line_radius > 0.0 ? s.line_radius : 0.004 * scene_radius;
  r.source = s.source_radius > 0.0 ? s.source_radius : 0.02 * scene_radius;
  return r;
}

// Casts and shades rows y = first, first + stride, ... The camera's eye is given relative to
// the Embree scene's origin.
struct Tracer {
  RTCScene scene;
  const Camera& camera;
  Vec3 eye;   // relative to the Embree origin
  const detail::ShadingSetup& shading;
  const RenderOptions& options;
  Image& image;

  void row(int y) const {
    const int S = options.supersample;
    const float inv = 1.0f / float(S * S);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    const detail::Color background = {float(options.background[0]), float(options.background[1]),
                                      float(options.background[2]), float(options.background[3])};
    for (int x = 0; x < camera.width; ++x) {
      detail::Color sum = {0, 0, 0, 0};
      for (int sy = 0; sy < S; ++sy)
        for (int sx = 0; sx < S; ++sx) {
          const double px = x + (sx + 0.5) / S, py = y + (sy + 0.5) / S;
          const Vec3 d = camera.direction(px, py);
          RTCRayHit rh;
          rh.ray.org_x = float(eye.x);
          rh.ray.org_y = float(eye.y);
          rh.ray.org_z = float(eye.z);
          rh.ray.dir_x = float(d.x);
          rh.ray.dir_y = float(d.y);
          rh.ray.dir_z = float(d.z);
          rh.ray.tnear = 0.0f;
          rh.ray.tfar = std::numeric_limits<float>::infinity();
          rh.ray.time = 0.0f;
          rh.ray.mask = 0xFFFFFFFFu;
          rh.ray.id = 0;
          rh.ray.flags = 0;
          rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
          rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
          rtcIntersect1(scene, &context, &rh);
          detail::Color c = background;
          if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
            detail::RayHit hit;
            hit.geometry = rh.hit.geomID;
            hit.primitive = rh.hit.primID;
            hit.u = rh.hit.u;
            hit.v = rh.hit.v;
            hit.normal = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
            hit.t = rh.ray.tfar;
            hit.direction = {double(rh.ray.dir_x), double(rh.ray.dir_y), double(rh.ray.dir_z)};
            c = detail::shade(shading, hit);
            c[3] = 255.0f;
          }
          for (int k = 0; k < 4; ++k) sum[k] += c[k];
        }
      Rgba out;
      for (int k = 0; k < 4; ++k) out[k] = std::uint8_t(std::clamp(std::lround(sum[k] * inv), 0L, 255L));
      image.set(x, y, out);
    }
  }
};

}  // namespace

Image render(const Scene& scene, const RenderOptions& options, RenderTimings* timings) {
  validate(options);
  validate(scene);
  const auto t0 = Clock::now();
  const BoundingSphere sphere = bounding_sphere(scene);
  const Camera camera = frame_camera(sphere, options);
  const Vec3 pixel_dx = (2.0 * camera.tan_half_x / camera.width) * camera.right;
  const Vec3 pixel_dy = (-2.0 * camera.tan_half_y / camera.height) * camera.up;
  const detail::ShadingSetup shading = detail::prepare_shading(scene, options, pixel_dx, pixel_dy);
  const detail::EmbreeScene embree(scene, sphere.center, radii_for(scene, sphere.radius));
  const double build = seconds_since(t0);

  const auto t1 = Clock::now();
  Image image(options.width, options.height, options.background);
  const Tracer tracer{embree.handle(), camera, camera.eye - sphere.center, shading, options, image};
  const int hardware = int(std::max(1u, std::thread::hardware_concurrency()));
  const int nthreads = std::clamp(options.threads > 0 ? options.threads : hardware, 1, options.height);
  // Rows are handed out one at a time: costs vary a lot between rows (sky vs. mesh).
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&] {
    try {
      for (int y = next++; y < options.height; y = next++) tracer.row(y);
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = options.height;
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < nthreads; ++i) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (timings) {
    timings->build = build;
    timings->trace = seconds_since(t1);
  }
  return image;
}

}  // namespace gsp::render
