// gsp-exact: exact (CGAL) or heat-method geodesic distances per vertex, written as .txt in the
// file's own vertex order. An independent cross-check of the accuracy figures of gsp-geodesic.
//
//   gsp-exact mesh.obj --source-vertex 0[,12,...] -o distances.txt [--method exact|heat|heat-idt]
#include <gsp/errors.hpp>
#include <gsp/io/atomic_file.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/reference/exact_geodesics.hpp>
#include <gsp/reference/heat_method.hpp>
#include <gsp/weld.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#ifndef GSP_VERSION
#define GSP_VERSION "0.1.0"
#endif

namespace {

const char* kUsage =
    "usage: gsp-exact [options] INPUT -o OUTPUT.txt\n"
    "\n"
    "Geodesic distances from source vertices by a reference method (CGAL; GPL), one value per\n"
    "line in the input file's vertex order (\"inf\" where unreachable).\n"
    "\n"
    "options:\n"
    "  -o, --output FILE         output .txt (required)\n"
    "  --source-vertex I[,J,...] source vertices, indices of the input file (required)\n"
    "  --method M                exact (default; CGAL Surface_mesh_shortest_path),\n"
    "                            heat (CGAL heat method), heat-idt (intrinsic Delaunay)\n"
    "  --weld-tolerance T        merge vertices closer than T before computing (default 0:\n"
    "                            identical positions and rounding noise, as the apps)\n"
    "  --no-weld                 use the vertices as stored\n"
    "  --stats FILE              timings and counts as JSON ('-' for stdout)\n"
    "  --quiet                   no summary on stderr (printed only to a terminal anyway)\n"
    "  -h, --help                this text\n"
    "  --version                 version\n";

struct Options {
  std::string input, output, stats, method = "exact";
  std::vector<long long> sources;
  double weld_tolerance = 0.0;
  bool weld = true, quiet = false;
};

struct UsageError {
  std::string what;
};

std::vector<long long> parse_index_list(const std::string& text) {
  std::vector<long long> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const long long v = std::strtoll(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || v < 0)
      throw UsageError{"--source-vertex: '" + item + "' is not a vertex index"};
    out.push_back(v);
  }
  if (out.empty()) throw UsageError{"--source-vertex needs at least one index"};
  return out;
}

// Returns false when the program should stop with exit code 0 (--help, --version).
bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= argc) throw UsageError{std::string(name) + " needs a value"};
      return argv[++i];
    };
    if (a == "-h" || a == "--help") {
      std::cout << kUsage;
      return false;
    } else if (a == "--version") {
      std::cout << "gsp-exact " << GSP_VERSION << "\n";
      return false;
    } else if (a == "-o" || a == "--output") {
      o.output = value("--output");
    } else if (a == "--source-vertex") {
      for (long long v : parse_index_list(value("--source-vertex"))) o.sources.push_back(v);
    } else if (a == "--method") {
      o.method = value("--method");
      if (o.method != "exact" && o.method != "heat" && o.method != "heat-idt")
        throw UsageError{"--method must be exact, heat or heat-idt, not '" + o.method + "'"};
    } else if (a == "--weld-tolerance") {
      const std::string t = value("--weld-tolerance");
      char* end = nullptr;
      o.weld_tolerance = std::strtod(t.c_str(), &end);
      if (t.empty() || *end != '\0' || !(o.weld_tolerance >= 0))
        throw UsageError{"--weld-tolerance: '" + t + "' is not a non-negative number"};
    } else if (a == "--no-weld") {
      o.weld = false;
    } else if (a == "--stats") {
      o.stats = value("--stats");
    } else if (a == "--quiet") {
      o.quiet = true;
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError{"unknown option '" + a + "'"};
    } else if (o.input.empty()) {
      o.input = a;
    } else {
      throw UsageError{"more than one input file ('" + o.input + "', '" + a + "')"};
    }
  }
  if (o.input.empty()) throw UsageError{"no input file"};
  if (o.output.empty()) throw UsageError{"no output file (-o FILE.txt)"};
  if (gsp::io::format_from_path(o.output) != gsp::io::Format::txt)
    throw UsageError{"the output must be a .txt file, not '" + o.output + "'"};
  if (o.sources.empty()) throw UsageError{"no source (--source-vertex I)"};
  return true;
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Stats {
  std::size_t file_vertices = 0, file_faces = 0, vertices = 0, reached = 0;
  double read = 0, build = 0, compute = 0, write = 0;
};

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

void write_stats(const Options& o, const Stats& s) {
  std::ostringstream json;
  json << "{\n  \"input\": {\"path\": " << json_string(o.input) << ", \"vertices\": " << s.file_vertices
       << ", \"faces\": " << s.file_faces << ", \"welded_vertices\": " << s.vertices << "},\n"
       << "  \"timings\": {\"read\": " << s.read << ", \"build\": " << s.build
       << ", \"compute\": " << s.compute << ", \"write\": " << s.write << "},\n"
       << "  \"counts\": {\"reached_vertices\": " << s.reached << "},\n"
       << "  \"settings\": {\"method\": " << json_string(o.method) << ", \"weld\": " << (o.weld ? "true" : "false")
       << ", \"weld_tolerance\": " << o.weld_tolerance << ", \"sources\": [";
  for (std::size_t i = 0; i < o.sources.size(); ++i) json << (i ? ", " : "") << o.sources[i];
  json << "]}\n}\n";
  if (o.stats == "-") {
    std::cout << json.str();
  } else {
    const std::string text = json.str();
    gsp::io::AtomicFile file(o.stats);
    file.write(text.data(), text.size());
    file.commit();
  }
}

int run(const Options& o) {
  Stats stats;
  auto t = Clock::now();
  gsp::io::ReadResult read = gsp::io::read_mesh(o.input);
  stats.read = seconds_since(t);
  stats.file_vertices = read.mesh.num_vertices();
  stats.file_faces = read.mesh.num_faces();
  for (long long v : o.sources)
    if (static_cast<std::size_t>(v) >= read.mesh.num_vertices())
      throw gsp::InvalidInput("--source-vertex " + std::to_string(v) + " does not exist (the file has " +
                              std::to_string(read.mesh.num_vertices()) + " vertices)");

  t = Clock::now();
  gsp::WeldResult welded;
  if (o.weld) {
    welded = gsp::weld_input(read.mesh, o.weld_tolerance);
  } else {
    welded.mesh = std::move(read.mesh);
    welded.vertex_map.resize(welded.mesh.num_vertices());
    for (std::size_t i = 0; i < welded.vertex_map.size(); ++i) welded.vertex_map[i] = gsp::Index(i);
  }
  stats.vertices = welded.mesh.num_vertices();
  std::vector<gsp::Index> sources;
  for (long long v : o.sources) sources.push_back(welded.vertex_map[static_cast<std::size_t>(v)]);

  std::vector<double> distances;
  if (o.method == "exact") {
    gsp::reference::ExactGeodesicSolver solver(welded.mesh);
    stats.build = seconds_since(t);
    t = Clock::now();
    std::vector<gsp::reference::ExactSource> exact_sources;
    for (gsp::Index v : sources) exact_sources.push_back(gsp::reference::ExactSource::at_vertex(v));
    distances = solver.distances(exact_sources);
  } else {
    gsp::reference::HeatMethodSolver solver(welded.mesh, o.method == "heat"
                                                             ? gsp::reference::HeatMethodMode::direct
                                                             : gsp::reference::HeatMethodMode::intrinsic_delaunay);
    stats.build = seconds_since(t);
    t = Clock::now();
    distances = solver.solve(sources);
  }
  stats.compute = seconds_since(t);
  for (double d : distances) stats.reached += d < std::numeric_limits<double>::infinity();

  t = Clock::now();
  gsp::io::write_values_txt(o.output, gsp::unweld_values(distances, welded.vertex_map));
  stats.write = seconds_since(t);
  if (!o.stats.empty()) write_stats(o, stats);
  // A summary for people at a terminal; scripts get nothing but the files.
  if (!o.quiet && isatty(fileno(stderr)))
    std::fprintf(stderr, "gsp-exact: %zu vertices (%zu after welding), %zu reached, %.3f s build, %.3f s compute\n",
                 stats.file_vertices, stats.vertices, stats.reached, stats.build, stats.compute);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    if (!parse(argc, argv, options)) return 0;
  } catch (const UsageError& e) {
    std::cerr << "gsp-exact: " << e.what << " (see --help)\n";
    return 2;
  }
  try {
    return run(options);
  } catch (const gsp::IoError& e) {
    std::cerr << "gsp-exact: " << e.what() << "\n";
  } catch (const gsp::Error& e) {
    std::cerr << "gsp-exact: " << options.input << ": " << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "gsp-exact: " << options.input << ": " << e.what() << "\n";
  }
  return 1;
}
