#include <gsp/cli/app.hpp>
#include <gsp/cli/memory.hpp>

#include <gsp/errors.hpp>
#include <gsp/io/atomic_file.hpp>

#include <cstdio>
#include <iostream>
#include <new>

#ifndef GSP_VERSION
#define GSP_VERSION "unknown"
#endif

namespace gsp::cli {

const char* version() { return GSP_VERSION; }

Context::Context(std::string name, bool quiet, std::string stats_path)
    : name_(std::move(name)), quiet_(quiet), stats_path_(std::move(stats_path)) {
  // Fixed section order, so every app's stats read the same way.
  stats_["app"] = name_;
  stats_["version"] = version();
  stats_["input"] = Json::object();
  stats_["settings"] = Json::object();
  stats_["operations"] = Json::object();
  stats_["timings"] = Json::object();
}

Context::~Context() = default;

std::unique_ptr<Progress> Context::progress(std::string label) const {
  return std::make_unique<Progress>(name_, std::move(label), !quiet_ && stderr_is_terminal());
}

void Context::note(const std::string& message) const {
  if (!quiet_) std::fprintf(stderr, "%s: %s\n", name_.c_str(), message.c_str());
}

void Context::open_stats() {
  // Opened before the work so that an unwritable stats path fails fast, not after an hour.
  if (stats_requested() && !stats_to_stdout()) stats_file_ = std::make_unique<io::AtomicFile>(stats_path_);
}

void Context::write_stats() {
  if (!stats_requested()) return;
  stats_["timings"] = timer_.to_json();
  timer_.write_memory(stats_["memory"], vertices_);
  const std::string text = stats_.dump() + "\n";
  if (stats_to_stdout()) {
    std::fwrite(text.data(), 1, text.size(), stdout);
  } else {
    stats_file_->write(text.data(), text.size());
    stats_file_->commit();
  }
}

std::string one_line_message(const std::string& message, const std::string& input_path,
                             bool prepend_input) {
  std::string m;
  if (prepend_input && !input_path.empty() && message.find(input_path) == std::string::npos)
    m = input_path + ": ";
  m += message;
  for (char& c : m)
    if (c == '\n' || c == '\r') c = ' ';
  while (!m.empty() && m.back() == ' ') m.pop_back();
  return m.empty() ? "unknown error" : m;
}

namespace {

int fail(const std::string& name, const std::string& message) {
  std::fflush(stdout);  // keep whatever the app already printed ahead of the error
  std::fprintf(stderr, "%s: error: %s\n", name.c_str(), message.c_str());
  return 1;
}

int usage_fail(const std::string& name, const std::string& message) {
  std::fprintf(stderr, "%s: error: %s\nRun with --help for more information.\n", name.c_str(),
               one_line_message(message, "", false).c_str());
  return 2;
}

}  // namespace

int run_app(int argc, char** argv, const std::string& name, const std::string& description,
            const SetupFn& setup, const BodyFn& body) {
  std::string input_path;  // for messages, once the body declared it
  return_large_frees_to_system();
  try {
    CLI::App app(description, name);
    bool quiet = false;
    std::string stats_path;
    app.set_version_flag("--version", name + " " + version(), "Print the version and exit");
    app.add_flag("-q,--quiet", quiet, "No progress and no remarks on stderr (errors are still printed)");
    app.add_option("--stats", stats_path,
                   "Write run statistics as JSON (counts, timings in seconds, settings) to FILE, "
                   "or to standard output for '-'")
        ->type_name("FILE|-");
    app.failure_message([name](const CLI::App*, const CLI::Error& e) {
      return name + ": error: " + e.what() + "\nRun with --help for more information.\n";
    });
    if (setup) setup(app);

    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      const int code = app.exit(e);  // prints help / version / the error
      std::cout.flush();
      return code == 0 ? 0 : 2;
    }

    Context ctx(name, quiet, stats_path);
    try {
      ctx.open_stats();
      body(ctx);
      ctx.write_stats();
      std::cout.flush();
      if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout)
        throw IoError("standard output", "", "write failed");
    } catch (...) {
      input_path = ctx.input_path();
      throw;
    }
    return 0;
  } catch (const UsageError& e) {
    return usage_fail(name, e.what());
  } catch (const CLI::Error& e) {  // CLI11 errors raised after parsing (e.g. by an option's callback)
    return usage_fail(name, e.what());
  } catch (const IoError& e) {
    return fail(name, one_line_message(e.what(), input_path, false));
  } catch (const Error& e) {  // InvalidInput, TopologyError and the rest of the hierarchy
    return fail(name, one_line_message(e.what(), input_path, true));
  } catch (const std::bad_alloc&) {
    return fail(name, one_line_message("out of memory", input_path, true));
  } catch (const std::exception& e) {
    return fail(name, one_line_message(e.what(), input_path, true));
  } catch (...) {
    return fail(name, "unknown error");
  }
}

}  // namespace gsp::cli
