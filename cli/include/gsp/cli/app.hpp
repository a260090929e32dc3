#pragma once
// The entry point every gsp-<app> main() goes through. It gives all apps the same contract
// (docs/cli.md):
//
//   --help, --version, --quiet/-q, --stats FILE|-
//   exit 0  success (also --help and --version)
//   exit 1  bad input or failure: ONE line on stderr, "gsp-NAME: error: <message>", where the
//           message names the file and the place (gsp::IoError does; InvalidInput and
//           TopologyError get the input file prepended when the app declared it with
//           Context::set_input). std::bad_alloc prints "out of memory".
//   exit 2  usage error: CLI11's parse errors and gsp::cli::UsageError, with a hint to --help.
//
// Nothing partial is left behind: outputs go through gsp::io::write_mesh / AtomicFile, and
// the --stats file is opened before the body runs and committed only after it succeeded.
//
// Usage (a whole app):
//
//   int main(int argc, char** argv) {
//     std::string input, output;
//     gsp::cli::LoadOptions load;
//     return gsp::cli::run_app(argc, argv, "gsp-example", "Does one thing to a mesh.",
//       [&](CLI::App& app) {                       // declare options, bound to locals
//         app.add_option("INPUT", input, "input mesh")->required();
//         app.add_option("-o,--output", output, "output mesh")->required();
//         gsp::cli::add_load_options(app, load);
//       },
//       [&](gsp::cli::Context& ctx) {              // do the work; throw on failure
//         auto in = gsp::cli::load_input(ctx, input, load);   // times "read", fills stats
//         { auto t = ctx.timer().scope("compute"); /* ... */ }
//         ctx.settings()["method"] = "gsp";
//         ctx.operations()["updates"] = 12345;
//         ctx.timer().time("write", [&] { gsp::io::write_mesh(output, in.file_mesh()); });
//       });
//   }
#include <gsp/cli/json.hpp>
#include <gsp/cli/progress.hpp>
#include <gsp/cli/timer.hpp>

#include <CLI/CLI.hpp>

#include <functional>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>

namespace gsp::io {
class AtomicFile;
}

namespace gsp::cli {

// A usage error found after parsing (a malformed "x,y,z", contradictory options):
// exit code 2 like CLI11's own parse errors.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The project version baked in at build time (GSP_VERSION from CMake's PROJECT_VERSION).
const char* version();

// What the body of an app gets: settings of the run, the stats being collected, progress.
class Context {
 public:
  Context(std::string name, bool quiet, std::string stats_path);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const std::string& name() const { return name_; }     // "gsp-info"
  bool quiet() const { return quiet_; }

  // The stats document. run_app fills "app", "version" and "timings"; the helpers below
  // address the contract's other sections. Apps may add more top-level keys (e.g. "result").
  Json& stats() { return stats_; }
  Json& input() { return stats_["input"]; }            // counts of what was read
  Json& settings() { return stats_["settings"]; }      // the method's settings
  Json& operations() { return stats_["operations"]; }  // operation counts
  PhaseTimer& timer() { return timer_; }
  // The mesh's vertex count (load_input sets it): the "memory" object of the stats then gives
  // the peaks per vertex too.
  void set_vertices(std::size_t n) { vertices_ = n; }

  bool stats_requested() const { return !stats_path_.empty(); }
  // True for "--stats -": stdout carries the stats JSON, so the app must print nothing else
  // there (gsp-info then skips its text report).
  bool stats_to_stdout() const { return stats_path_ == "-"; }

  // A progress line on stderr; silent unless stderr is a terminal and --quiet is off.
  // Hand progress.callback() to the library.
  std::unique_ptr<Progress> progress(std::string label) const;

  // A remark on stderr ("gsp-NAME: <message>"), unless --quiet. Not for errors: throw those.
  void note(const std::string& message) const;

  // The input file, used to name the file in InvalidInput / TopologyError messages.
  void set_input(std::string path) { input_path_ = std::move(path); }
  const std::string& input_path() const { return input_path_; }

  // Called by run_app: open the --stats file before the work, write it after.
  void open_stats();
  void write_stats();

 private:
  std::string name_;
  bool quiet_;
  std::string stats_path_;
  std::string input_path_;
  Json stats_;
  PhaseTimer timer_;
  std::size_t vertices_ = 0;
  std::unique_ptr<io::AtomicFile> stats_file_;
};

// Declares the app's options on the CLI11 app (bind them to variables the body reads).
using SetupFn = std::function<void(CLI::App&)>;
// The work; reports failure by throwing (gsp::Error, UsageError, anything std::exception).
using BodyFn = std::function<void(Context&)>;

// Builds the CLI11 app named `name` with the common options plus those `setup` declares,
// parses argv, runs `body`, writes --stats, and returns the exit code for main().
// Never throws.
int run_app(int argc, char** argv, const std::string& name, const std::string& description,
            const SetupFn& setup, const BodyFn& body);

// The message run_app prints for an exception (one line: newlines become spaces; the input
// file is prepended to InvalidInput / TopologyError messages that do not name it).
// Exposed for tests.
std::string one_line_message(const std::string& message, const std::string& input_path,
                             bool prepend_input);

}  // namespace gsp::cli
