#include "report.hpp"

#include <string>

namespace gsp::info {

namespace {

cli::Json topology_json(const TopologyReport& t) {
  cli::Json j = cli::Json::object();
  j["vertices"] = t.vertices;
  j["faces"] = t.faces;
  j["edges"] = t.edges;
  j["boundary_edges"] = t.boundary_edges;
  j["boundary_loops"] = t.boundary_loops;
  j["nonmanifold_edges"] = t.nonmanifold_edges;
  j["nonmanifold_vertices"] = t.nonmanifold_vertices;
  j["inconsistent_edges"] = t.inconsistent_edges;
  j["components"] = t.components;
  j["repeated_index_faces"] = t.repeated_index_faces;
  j["zero_area_faces"] = t.zero_area_faces;
  j["duplicate_faces"] = t.duplicate_faces;
  j["isolated_vertices"] = t.isolated_vertices;
  j["euler_characteristic"] = static_cast<long long>(t.euler_characteristic);
  j["manifold"] = t.is_manifold();
  j["closed"] = t.is_closed();
  return j;
}

cli::Json summary_json(const Summary& s) {
  cli::Json j = cli::Json::object();
  j["count"] = s.count;
  j["min"] = s.min;
  j["mean"] = s.mean;
  j["median"] = s.median;
  j["p99"] = s.p99;
  j["max"] = s.max;
  j["stddev"] = s.stddev;
  return j;
}

cli::Json vec_json(Vec3 v) {
  cli::Json j = cli::Json::array();
  j.push_back(v.x);
  j.push_back(v.y);
  j.push_back(v.z);
  return j;
}

}  // namespace

cli::Json to_json(const Report& r) {
  cli::Json j = cli::Json::object();
  cli::Json& file = j["file"];
  file["path"] = r.path;
  file["format"] = io::format_name(r.info.format);
  file["binary"] = r.info.binary;
  file["vertices"] = r.info.file_vertices;
  file["faces"] = r.info.file_faces;
  file["triangles"] = r.triangles;
  file["polygons_split"] = r.info.polygons_split;
  file["has_normals"] = r.info.has_normals;
  file["notes"] = cli::Json::array_of(r.info.notes);
  cli::Json& weld = j["weld"];
  weld["enabled"] = r.weld_enabled;
  weld["tolerance"] = r.weld_tolerance;
  weld["vertices"] = r.welded_vertices;
  weld["merged"] = r.merged_vertices;
  j["point_cloud"] = r.point_cloud;
  if (!r.point_cloud) {
    j["topology"]["raw"] = topology_json(r.raw);
    j["topology"]["welded"] = topology_json(r.welded);
  }
  cli::Json& g = j["geometry"];
  g["bbox"]["min"] = vec_json(r.bbox.min);
  g["bbox"]["max"] = vec_json(r.bbox.max);
  g["bbox"]["diagonal"] = r.bbox.diagonal();
  if (!r.point_cloud) {
    g["edge_length"] = summary_json(r.edge_length);
    g["anisotropy"] = r.shape.anisotropy;
    g["aspect_ratio"] = summary_json(r.shape.aspect_ratio);
    g["aspect_ratio"]["above_10"] = r.shape.aspect_ratio_above_10;
    g["degenerate_faces"] = r.shape.degenerate_faces;
    g["max_valence"] = r.max_valence;
  }
  if (r.layout) {
    cli::Json& l = j["layout"];
    l["mean_neighbour_index_distance_before"] = r.layout->before;
    l["mean_neighbour_index_distance_after"] = r.layout->after;
    l["seconds"] = r.layout->seconds;
  }
  return j;
}

namespace {

// "label" padded to a column, then the value: the text report is read by eye and by grep.
void row(std::FILE* out, const char* label, const std::string& value) {
  std::fprintf(out, "  %-24s %s\n", label, value.c_str());
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string vec(Vec3 v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }

void topo_row(std::FILE* out, const char* label, std::size_t raw, std::size_t welded) {
  std::fprintf(out, "  %-24s %12zu %12zu\n", label, raw, welded);
}

}  // namespace

void print_text(const Report& r, std::FILE* out) {
  std::fprintf(out, "%s\n", r.path.c_str());
  row(out, "format", std::string(io::format_name(r.info.format)) + (r.info.binary ? " (binary)" : " (ascii)"));
  row(out, "file vertices", std::to_string(r.info.file_vertices));
  row(out, "file faces", std::to_string(r.info.file_faces) +
                             (r.info.polygons_split ? " (" + std::to_string(r.info.polygons_split) +
                                                          " polygons fan-triangulated into " +
                                                          std::to_string(r.triangles) + " triangles)"
                                                    : ""));
  if (r.weld_enabled)
    row(out, "welded vertices", std::to_string(r.welded_vertices) + " (" + std::to_string(r.merged_vertices) +
                                    " merged, tolerance " + num(r.weld_tolerance) + ")");
  else
    row(out, "welded vertices", "not welded (--no-weld)");
  for (const std::string& n : r.info.notes) row(out, "note", n);

  if (!r.point_cloud) {
    std::fprintf(out, "\ntopology%*s %12s %12s\n", 18, "", "raw", "welded");
    const TopologyReport &a = r.raw, &b = r.welded;
    topo_row(out, "vertices", a.vertices, b.vertices);
    topo_row(out, "faces", a.faces, b.faces);
    topo_row(out, "edges", a.edges, b.edges);
    topo_row(out, "boundary edges", a.boundary_edges, b.boundary_edges);
    topo_row(out, "boundary loops", a.boundary_loops, b.boundary_loops);
    topo_row(out, "non-manifold edges", a.nonmanifold_edges, b.nonmanifold_edges);
    topo_row(out, "non-manifold vertices", a.nonmanifold_vertices, b.nonmanifold_vertices);
    topo_row(out, "inconsistent edges", a.inconsistent_edges, b.inconsistent_edges);
    topo_row(out, "components", a.components, b.components);
    topo_row(out, "repeated-index faces", a.repeated_index_faces, b.repeated_index_faces);
    topo_row(out, "zero-area faces", a.zero_area_faces, b.zero_area_faces);
    topo_row(out, "duplicate faces", a.duplicate_faces, b.duplicate_faces);
    topo_row(out, "isolated vertices", a.isolated_vertices, b.isolated_vertices);
    std::fprintf(out, "  %-24s %12lld %12lld\n", "Euler characteristic",
                 static_cast<long long>(a.euler_characteristic), static_cast<long long>(b.euler_characteristic));
    std::fprintf(out, "  %-24s %12s %12s\n", "manifold", a.is_manifold() ? "yes" : "no", b.is_manifold() ? "yes" : "no");
    std::fprintf(out, "  %-24s %12s %12s\n", "closed", a.is_closed() ? "yes" : "no", b.is_closed() ? "yes" : "no");
  }

  std::fprintf(out, "\ngeometry\n");
  row(out, "bounding box min", vec(r.bbox.min));
  row(out, "bounding box max", vec(r.bbox.max));
  row(out, "bounding box diagonal", num(r.bbox.diagonal()));
  if (!r.point_cloud) {
    const Summary& e = r.edge_length;
    row(out, "edge length", "min " + num(e.min) + "  mean " + num(e.mean) + "  max " + num(e.max) +
                                "  stddev " + num(e.stddev) + "  (" + std::to_string(e.count) + " edges)");
    row(out, "anisotropy", num(r.shape.anisotropy) + "  (mean longest/shortest edge)");
    const Summary& a = r.shape.aspect_ratio;
    row(out, "aspect ratio", "min " + num(a.min) + "  median " + num(a.median) + "  mean " + num(a.mean) +
                                 "  p99 " + num(a.p99) + "  max " + num(a.max));
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.3g%%", 100.0 * r.shape.aspect_ratio_above_10);
    row(out, "aspect ratio > 10", std::string(percent) + " of " +
                                      std::to_string(a.count) + " non-degenerate triangles");
    row(out, "degenerate faces", std::to_string(r.shape.degenerate_faces));
    row(out, "max valence", std::to_string(r.max_valence));
  } else {
    row(out, "faces", "none (point cloud)");
  }

  if (r.layout) {
    std::fprintf(out, "\nlayout\n");
    row(out, "neighbour index gap", "before " + num(r.layout->before) + "  after " + num(r.layout->after) +
                                             "  (mean |i-j| over edges)");
    row(out, "layout time", num(r.layout->seconds) + " s");
  }
}

}  // namespace gsp::info
