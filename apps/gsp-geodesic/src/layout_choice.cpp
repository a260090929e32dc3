#include "layout_choice.hpp"

#include <gsp/layout.hpp>

namespace gsp::geodesic_app {

LayoutChoice choose_layout(const std::string& mode, const TriangleMesh& mesh, bool one_field) {
  LayoutChoice c;
  if (mode == "on") return c.reason = "--layout on", c;
  if (mode == "off") return c.optimize = false, c.reason = "--layout off", c;
  if (!one_field) return c.reason = "several fields: the layout pays back", c;
  const OrderCoherence o = order_coherence(mesh);
  c.file_gap = o.file_log_gap;
  c.random_gap = o.random_log_gap;
  c.optimize = !o.coherent;
  c.reason = c.optimize ? "one field, the file's order is scattered" : "one field, the file's order is coherent";
  return c;
}

}  // namespace gsp::geodesic_app
