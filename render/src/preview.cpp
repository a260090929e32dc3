#include <gsp/render/render.hpp>

namespace gsp::render {

void render_field_preview(const std::string& png_path, const TriangleMesh& mesh,
                          const std::vector<double>& vertex_field, const std::vector<Vec3>& source_points,
                          const RenderOptions& options) {
  Scene scene;
  scene.mesh.positions = mesh.positions;
  scene.mesh.triangles = mesh.triangles;   // normals are not used: the renderer computes its own
  scene.vertex_field = vertex_field;
  scene.sources = source_points;
  write_png(png_path, render(scene, options));
}

}  // namespace gsp::render
