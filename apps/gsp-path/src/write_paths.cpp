#include "write_paths.hpp"

#include <gsp/cli/json.hpp>
#include <gsp/io/atomic_file.hpp>
#include <gsp/io/polyline_io.hpp>

#include <algorithm>
#include <cctype>

namespace gsp::path_app {

namespace {

bool ends_with_json(std::string p) {
  std::transform(p.begin(), p.end(), p.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return p.size() >= 5 && p.compare(p.size() - 5, 5, ".json") == 0;
}

void write_json(const std::string& path, const std::vector<pathfinding::GeodesicPath>& paths) {
  cli::Json doc = cli::Json::object();
  cli::Json& list = doc["paths"] = cli::Json::array();
  for (const pathfinding::GeodesicPath& p : paths) {
    cli::Json j = cli::Json::object();
    j["found"] = p.found();
    if (p.found()) {
      j["length"] = p.length;
      j["field_distance"] = p.field_distance;
      cli::Json& pts = j["points"] = cli::Json::array();
      for (const pathfinding::PathPoint& q : p.points) {
        cli::Json point = cli::Json::object();
        point["face"] = q.point.element;
        point["barycentric"] = cli::Json::array_of(q.point.barycentric);
        point["position"] = cli::Json::array_of(std::vector<double>{q.position.x, q.position.y, q.position.z});
        pts.push_back(std::move(point));
      }
    }
    list.push_back(std::move(j));
  }
  const std::string text = doc.dump() + "\n";
  io::AtomicFile file(path);
  file.write(text.data(), text.size());
  file.commit();
}

}  // namespace

void write_paths(const std::string& path, const std::vector<pathfinding::GeodesicPath>& paths) {
  if (ends_with_json(path)) return write_json(path, paths);
  std::vector<std::vector<Vec3>> lines;
  for (const pathfinding::GeodesicPath& p : paths) {
    if (!p.found()) continue;
    std::vector<Vec3> line;
    for (const pathfinding::PathPoint& q : p.points) line.push_back(q.position);
    lines.push_back(std::move(line));
  }
  io::write_polylines(path, lines);
}

}  // namespace gsp::path_app
