#include "layout_choice.hpp"

namespace gsp::geodesic_app {

LayoutChoice choose_layout(const std::string& mode, const TriangleMesh& mesh, bool one_field) {
  LayoutChoice c;
  if (mode == "on") return c.reason = "--layout on", c;
  if (mode == "off") return c.optimize = false, c.reason = "--layout off", c;
  if (!one_field) return c.reason = "several fields: the layout pays back", c;
  c.order = order_coherence(mesh);
  if (c.order.sort_faces)
    return c.faces_only = true, c.reason = "one field, the file's vertices are coherent, its faces scattered", c;
  c.optimize = !c.order.coherent;
  c.spatial = c.optimize;
  c.reason = c.optimize ? "one field, the file's order is scattered" : "one field, the file's order is coherent";
  return c;
}

}  // namespace gsp::geodesic_app
