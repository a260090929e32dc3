// Unit tests of gsp::cli: JSON writer, option parsers, phase timer, error lines, mesh loading.
#include "apps_support.hpp"
#include "test_data.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/json.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/cli/progress.hpp>
#include <gsp/cli/memory.hpp>
#include <gsp/cli/timer.hpp>
#include <gsp/errors.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <new>

namespace {

using gsp::cli::Json;
using gsp::test::parse_json;

TEST(CliJson, EscapesStringsAndParsesBack) {
  Json j;
  const std::string nasty = std::string("quote\" backslash\\ newline\n tab\t bell\x07 del\x7f utf8 \xc3\xa9");
  j["s"] = nasty;
  const std::string text = j.dump();
  EXPECT_NE(text.find("\\u0007"), std::string::npos);
  EXPECT_NE(text.find("\\u007f"), std::string::npos);
  EXPECT_NE(text.find("\\n"), std::string::npos);
  EXPECT_EQ(parse_json(text)["s"].str, std::string("quote\" backslash\\ newline\n tab\t bell\x07 del\x7f utf8 \xc3\xa9"));
}

TEST(CliJson, DoublesRoundTripAndNonFiniteIsNull) {
  Json j;
  const double third = 1.0 / 3.0, tiny = 4.9e-324, big = 1.7976931348623157e308;
  j["third"] = third;
  j["tiny"] = tiny;
  j["big"] = big;
  j["nan"] = std::numeric_limits<double>::quiet_NaN();
  j["inf"] = -std::numeric_limits<double>::infinity();
  j["int"] = -42;
  j["size"] = std::size_t{18446744073709551615ull};
  const auto v = parse_json(j.dump());
  EXPECT_EQ(v["third"].num, third);  // %.17g reads back bit-identical
  EXPECT_EQ(v["tiny"].num, tiny);
  EXPECT_EQ(v["big"].num, big);
  EXPECT_EQ(v["nan"].type, gsp::test::JsonValue::null);
  EXPECT_EQ(v["inf"].type, gsp::test::JsonValue::null);
  EXPECT_EQ(v["int"].num, -42.0);
  EXPECT_NE(j.dump().find("18446744073709551615"), std::string::npos);
}

TEST(CliJson, NumbersAreShortButExact) {
  auto text = [](double d) {
    std::string s;
    gsp::cli::append_json_number(s, d);
    return s;
  };
  EXPECT_EQ(text(0.1), "0.1");
  EXPECT_EQ(text(-75.6563), "-75.6563");
  EXPECT_EQ(text(1.0 / 3.0), "0.3333333333333333");    // 16 digits
  EXPECT_EQ(text(0.1 + 0.2), "0.30000000000000004");   // needs all 17
  EXPECT_EQ(text(2.0), "2");
  // Exact for arbitrary bit patterns (deterministic LCG over finite doubles).
  std::uint64_t x = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < 10000; ++i) {
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    double d;
    std::memcpy(&d, &x, sizeof d);
    if (!std::isfinite(d)) continue;
    EXPECT_EQ(std::strtod(text(d).c_str(), nullptr), d) << text(d);
  }
}

TEST(CliJson, NestedObjectsKeepOrderAndReferencesStayValid) {
  Json j;
  Json& a = j["a"];
  a["x"] = 1;
  for (int i = 0; i < 100; ++i) j["k" + std::to_string(i)] = i;  // grows j after taking `a`
  a["y"] = 2;                                                      // still valid
  j["list"] = Json::array();
  j["list"].push_back(1.5);
  j["list"].push_back("two");
  j["list"].push_back(Json::object());
  j["empty"] = Json::object();
  const std::string compact = j.dump(-1);
  EXPECT_EQ(compact.rfind("{\"a\":{\"x\":1,\"y\":2},\"k0\":0,\"k1\":1,", 0), 0u) << compact;
  const auto v = parse_json(j.dump());
  EXPECT_EQ(v["a"]["y"].num, 2.0);
  EXPECT_EQ(v["k99"].num, 99.0);
  ASSERT_EQ(v["list"].items.size(), 3u);
  EXPECT_EQ(v["list"].items[1].str, "two");
  EXPECT_EQ(v["empty"].members.size(), 0u);
  EXPECT_EQ(j.size(), 103u);
  EXPECT_THROW(j["list"]["x"], std::logic_error);
}

TEST(CliParse, IndexLists) {
  EXPECT_EQ(gsp::cli::parse_index_list("1,2,3", "--v"), (std::vector<gsp::Index>{1, 2, 3}));
  EXPECT_EQ(gsp::cli::parse_index_list(" 7 , 0", "--v"), (std::vector<gsp::Index>{7, 0}));
  for (const char* bad : {"", "1,,2", "1,", "-1", "+1", "1.5", "x", "4294967295", "99999999999999999999"})
    EXPECT_THROW(gsp::cli::parse_index_list(bad, "--v"), gsp::cli::UsageError) << bad;
  try {
    gsp::cli::parse_index_list("1,x,3", "--source-vertex");
    FAIL();
  } catch (const gsp::cli::UsageError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--source-vertex"), std::string::npos) << m;
    EXPECT_NE(m.find("\"x\""), std::string::npos) << m;
  }
}

TEST(CliParse, VectorsAndFacePoints) {
  const gsp::Vec3 p = gsp::cli::parse_vec3("1.5,-2,3e-1", "--p");
  EXPECT_DOUBLE_EQ(p.x, 1.5);
  EXPECT_DOUBLE_EQ(p.y, -2.0);
  EXPECT_DOUBLE_EQ(p.z, 0.3);
  for (const char* bad : {"1,2", "1,2,3,4", "1,nan,2", "1,inf,2", "a,b,c", "1,2,1e999"})
    EXPECT_THROW(gsp::cli::parse_vec3(bad, "--p"), gsp::cli::UsageError) << bad;

  const auto fp = gsp::cli::parse_face_point("12:0.25,0.5", "--f");
  EXPECT_FALSE(fp.is_vertex());
  EXPECT_EQ(fp.element, 12u);
  EXPECT_DOUBLE_EQ(fp.barycentric[0], 0.25);
  EXPECT_DOUBLE_EQ(fp.barycentric[1], 0.25);
  EXPECT_DOUBLE_EQ(fp.barycentric[2], 0.5);
  for (const char* bad : {"12", "12:0.5", "x:0.1,0.1", "-1:0.1,0.1", "3:0.7,0.7", "3:-0.1,0.5", "3:0.1,0.2,0.3"})
    EXPECT_THROW(gsp::cli::parse_face_point(bad, "--f"), gsp::cli::UsageError) << bad;
}

TEST(CliParse, OutputFormat) {
  using gsp::io::Format;
  EXPECT_EQ(gsp::cli::output_format("a/b.PLY", {Format::ply, Format::obj}), Format::ply);
  EXPECT_THROW(gsp::cli::output_format("a.stl", {Format::ply, Format::obj}), gsp::cli::UsageError);
  EXPECT_THROW(gsp::cli::output_format("noext", {Format::ply}), gsp::cli::UsageError);
}

TEST(CliTimer, AccumulatesPhasesInOrder) {
  gsp::cli::PhaseTimer t;
  t.add("read", 0.5);
  t.add("compute", 1.0);
  t.add("read", 0.25);
  EXPECT_DOUBLE_EQ(t.seconds("read"), 0.75);
  EXPECT_DOUBLE_EQ(t.seconds("never"), 0.0);
  const int forty_two = t.time("write", [] { return 42; });
  EXPECT_EQ(forty_two, 42);
  EXPECT_GE(t.seconds("write"), 0.0);
  {
    auto s = t.scope("layout");
  }
  const std::string text = t.to_json().dump(-1);
  EXPECT_EQ(text.rfind("{\"read\":0.75,\"compute\":1,\"write\":", 0), 0u) << text;
  const auto v = parse_json(text);
  EXPECT_TRUE(v.has("layout"));
  EXPECT_GE(v["total"].num, 0.0);
}

// The peak resident memory after each phase: a real reading of this process (it holds at
// least the 64 MB touched here), never lower for a later phase, per vertex when told the count.
TEST(CliTimer, PeakMemoryPerPhase) {
  gsp::cli::PhaseTimer t;
  t.add("read", 0.1);
  std::vector<char> block(64u << 20);
  for (std::size_t i = 0; i < block.size(); i += 4096) block[i] = char(i);
  t.add("compute", 0.2);
  const gsp::cli::ResidentMemory now = gsp::cli::resident_memory();
  EXPECT_GE(now.current, block.size());
  EXPECT_GE(now.peak, now.current);
  gsp::cli::Json memory = gsp::cli::Json::object();
  memory["state_bytes_per_vertex"] = 1.5;   // an app's own member stays
  t.write_memory(memory, 1000);
  const auto v = parse_json(memory.dump(-1));
  EXPECT_EQ(v["state_bytes_per_vertex"].num, 1.5);
  const double read = v["peak_after"]["read"].num, compute = v["peak_after"]["compute"].num;
  EXPECT_GT(read, 0.0);
  EXPECT_GE(compute, read);
  EXPECT_GE(compute, 0.95 * double(now.current));   // the block was resident when compute ended
  EXPECT_GE(v["peak_bytes"].num, compute);
  EXPECT_DOUBLE_EQ(v["peak_after_per_vertex"]["compute"].num, compute / 1000);
  EXPECT_EQ(int(block[4096]), int(char(4096)));
}

TEST(CliErrors, OneLineMessages) {
  using gsp::cli::one_line_message;
  EXPECT_EQ(one_line_message("a\nb\r\n", "", true), "a b");
  EXPECT_EQ(one_line_message("vertex 3 is bad", "m.obj", true), "m.obj: vertex 3 is bad");
  EXPECT_EQ(one_line_message("m.obj:line 3: bad", "m.obj", true), "m.obj:line 3: bad");  // names it already
  EXPECT_EQ(one_line_message("x", "m.obj", false), "x");
  EXPECT_EQ(one_line_message("", "", false), "unknown error");
}

TEST(CliLoad, WeldsStlAndMapsBackToFileOrder) {
  gsp::test::ScratchDir dir("cli");
  // Two triangles of a unit square as an ASCII STL soup: 6 stored vertices, 4 distinct.
  const std::string stl =
      "solid sq\n"
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n"
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n"
      "endsolid sq\n";
  gsp::test::write_file(dir / "sq.stl", stl);
  const std::string path = (dir / "sq.stl").string();

  const auto in = gsp::cli::load_mesh(path, {});
  EXPECT_TRUE(in.welded);
  EXPECT_EQ(in.mesh.num_vertices(), 4u);
  EXPECT_EQ(in.file_vertices(), 6u);
  EXPECT_EQ(in.merged, 2u);
  EXPECT_EQ(in.file_mesh().num_vertices(), 6u);
  EXPECT_EQ(in.mesh.num_faces(), 2u);
  // Values per welded vertex come back one per stored vertex, equal on merged copies.
  std::vector<double> per_vertex(in.mesh.num_vertices());
  for (std::size_t v = 0; v < per_vertex.size(); ++v) per_vertex[v] = in.mesh.positions[v].x + 10 * in.mesh.positions[v].y;
  const auto back = in.to_file_order(per_vertex);
  ASSERT_EQ(back.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    const gsp::Vec3 p = in.file_mesh().positions[i];
    EXPECT_DOUBLE_EQ(back[i], p.x + 10 * p.y);
  }
  EXPECT_THROW(in.mesh_vertex(6), gsp::InvalidInput);

  gsp::cli::LoadOptions never;
  never.weld = gsp::cli::WeldMode::never;
  const auto raw = gsp::cli::load_mesh(path, never);
  EXPECT_FALSE(raw.welded);
  EXPECT_EQ(raw.mesh.num_vertices(), 6u);
  EXPECT_EQ(raw.mesh_vertex(5), 5u);
}

TEST(CliLoad, PointCloudIsAnErrorUnlessAccepted) {
  gsp::test::ScratchDir dir("cli");
  gsp::test::write_file(dir / "p.xyz", "0 0 0\n1 0 0\n0 1 0\n");
  const std::string path = (dir / "p.xyz").string();
  try {
    gsp::cli::load_mesh(path, {});
    FAIL();
  } catch (const gsp::IoError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
  gsp::cli::LoadOptions accept;
  accept.require_faces = false;
  EXPECT_EQ(gsp::cli::load_mesh(path, accept).mesh.num_vertices(), 3u);
}

// Coordinates no module can square (gsp::validate_positions): one line naming the file and
// the vertex, for every app, instead of distances of 0 everywhere.
TEST(CliLoad, CoordinatesOutOfRangeAreAnError) {
  gsp::test::ScratchDir dir("cli");
  gsp::test::write_file(dir / "far.off", "OFF\n3 1 0\n0 0 0\n1e300 0 0\n0 1e300 0\n3 0 1 2\n");
  gsp::test::write_file(dir / "near.off", "OFF\n3 1 0\n0 0 0\n1e-300 0 0\n0 1e-300 0\n3 0 1 2\n");
  for (const char* name : {"far.off", "near.off"}) {
    const std::string path = (dir / name).string();
    try {
      gsp::cli::load_mesh(path, {});
      FAIL() << name;
    } catch (const gsp::Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path), std::string::npos) << what;
      EXPECT_NE(what.find("scale the input"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(CliLoad, ToleranceMergesNearbyVertices) {
  gsp::test::ScratchDir dir("cli");
  gsp::test::write_file(dir / "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1.0000001 0 0\nv 1 1 0\nf 1 2 3\nf 4 5 3\n");
  gsp::cli::LoadOptions o;
  o.weld = gsp::cli::WeldMode::always;
  EXPECT_EQ(gsp::cli::load_mesh((dir / "t.obj").string(), o).mesh.num_vertices(), 5u);
  o.weld_tolerance = 1e-5;
  EXPECT_EQ(gsp::cli::load_mesh((dir / "t.obj").string(), o).mesh.num_vertices(), 4u);
}

}  // namespace

namespace {

// Runs run_app in-process with `args` and a body, capturing stdout and stderr.
struct AppRun {
  int code;
  std::string out, err;
};
AppRun run_app_with(std::vector<std::string> args, const gsp::cli::BodyFn& body) {
  args.insert(args.begin(), "gsp-test");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::string input;
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const int code = gsp::cli::run_app(
      static_cast<int>(args.size()), argv.data(), "gsp-test", "A test app.",
      [&](CLI::App& app) { app.add_option("INPUT", input); },
      [&](gsp::cli::Context& ctx) {
        ctx.set_input("in.obj");
        body(ctx);
      });
  AppRun r{code, "", ""};
  r.out = ::testing::internal::GetCapturedStdout();
  r.err = ::testing::internal::GetCapturedStderr();
  return r;
}

TEST(CliRunApp, MapsExceptionsToExitCodesAndOneLine) {
  struct Case {
    std::function<void()> thrower;
    int code;
    std::string err;
  };
  const std::vector<Case> cases = {
      {[] { throw gsp::IoError("in.obj", "line 3", "bad token"); }, 1, "gsp-test: error: in.obj:line 3: bad token\n"},
      {[] { throw gsp::InvalidInput("source vertex 9 does not exist"); }, 1,
       "gsp-test: error: in.obj: source vertex 9 does not exist\n"},
      {[] { throw gsp::TopologyError("needs a manifold\nmesh"); }, 1, "gsp-test: error: in.obj: needs a manifold mesh\n"},
      {[] { throw std::bad_alloc(); }, 1, "gsp-test: error: in.obj: out of memory\n"},
      {[] { throw std::runtime_error("boom"); }, 1, "gsp-test: error: in.obj: boom\n"},
      {[] { throw 42; }, 1, "gsp-test: error: unknown error\n"},
      {[] { throw gsp::cli::UsageError("--x: \"y\": bad"); }, 2,
       "gsp-test: error: --x: \"y\": bad\nRun with --help for more information.\n"},
  };
  for (const Case& c : cases) {
    const AppRun r = run_app_with({"in.obj"}, [&](gsp::cli::Context&) { c.thrower(); });
    EXPECT_EQ(r.code, c.code) << c.err;
    EXPECT_EQ(r.err, c.err);
    EXPECT_EQ(r.out, "");
  }
}

TEST(CliRunApp, ParseErrorsHelpVersionAndStats) {
  const auto noop = [](gsp::cli::Context&) {};
  const AppRun bad = run_app_with({"--nope"}, noop);
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.err.rfind("gsp-test: error: ", 0), 0u) << bad.err;

  const AppRun version = run_app_with({"--version"}, noop);
  EXPECT_EQ(version.code, 0);
  EXPECT_EQ(version.out, std::string("gsp-test ") + gsp::cli::version() + "\n");

  const AppRun help = run_app_with({"--help"}, noop);
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("--stats"), std::string::npos);

  const AppRun stats = run_app_with({"in.obj", "--stats", "-", "-q"}, [](gsp::cli::Context& ctx) {
    EXPECT_TRUE(ctx.quiet());
    EXPECT_TRUE(ctx.stats_to_stdout());
    ctx.input()["vertices"] = 3;
    ctx.operations()["updates"] = 7;
    ctx.timer().add("compute", 0.5);
  });
  ASSERT_EQ(stats.code, 0) << stats.err;
  const auto j = parse_json(stats.out);
  EXPECT_EQ(j["app"].str, "gsp-test");
  EXPECT_EQ(j["input"]["vertices"].num, 3.0);
  EXPECT_EQ(j["operations"]["updates"].num, 7.0);
  EXPECT_EQ(j["timings"]["compute"].num, 0.5);
  EXPECT_TRUE(j["timings"].has("total"));
}

TEST(CliRunApp, StatsFileOnlyOnSuccess) {
  gsp::test::ScratchDir dir("cli");
  const std::string path = (dir / "s.json").string();
  const AppRun failed = run_app_with({"in.obj", "--stats", path}, [](gsp::cli::Context&) { throw gsp::Error("x"); });
  EXPECT_EQ(failed.code, 1);
  EXPECT_TRUE(dir.entries().empty());  // neither the file nor its temporary
  const AppRun ok = run_app_with({"in.obj", "--stats", path}, [](gsp::cli::Context& ctx) { ctx.settings()["k"] = "v"; });
  EXPECT_EQ(ok.code, 0);
  EXPECT_EQ(parse_json(gsp::test::slurp(path))["settings"]["k"].str, "v");
}

TEST(CliProgress, DisabledReporterIsSilentAndHasNoCallback) {
  gsp::cli::Progress p("gsp-test", "computing", false);
  EXPECT_FALSE(p.enabled());
  EXPECT_FALSE(static_cast<bool>(p.callback()));
  ::testing::internal::CaptureStderr();
  p.update(0.5);
  p.finish();
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST(CliProgress, EnabledReporterDrawsAndErasesItsLine) {
  ::testing::internal::CaptureStderr();
  {
    gsp::cli::Progress p("gsp-test", "computing", true);
    auto cb = p.callback();
    ASSERT_TRUE(static_cast<bool>(cb));
    cb(0.0);
    cb(0.001);   // same percent: no redraw
    cb(1.0);     // 100% always drawn
  }
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(err, "\rgsp-test: computing   0%\rgsp-test: computing 100%\r\033[K");
}

}  // namespace
