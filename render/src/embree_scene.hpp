#pragma once
// The Embree side of render(): device and scene built from a gsp::render::Scene, released
// with the object. Positions are stored as floats relative to `origin` (the bounding sphere's
// centre) so that models far from the world origin keep their precision.
#include <gsp/render/scene.hpp>

#include <embree3/rtcore.h>

namespace gsp::render::detail {

// Geometry ids as attached, so a hit's geomID says what was hit.
enum GeometryId : unsigned { kMeshGeometry = 0, kPointGeometry = 1, kLineGeometry = 2, kSourceGeometry = 3 };

struct Radii {
  double point = 0.0, line = 0.0, source = 0.0;
};

class EmbreeScene {
 public:
  // Throws gsp::Error when Embree cannot build the scene (no device, unsupported geometry).
  EmbreeScene(const Scene& scene, Vec3 origin, const Radii& radii);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCScene handle() const { return scene_; }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace gsp::render::detail
