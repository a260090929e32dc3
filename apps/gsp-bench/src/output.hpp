#pragma once
// An output given by path: opened (and checked writable) before the work, committed
// atomically after (io::AtomicFile: a reader never sees half a report); "-" is stdout.
#include <gsp/io/atomic_file.hpp>

#include <cstdio>
#include <memory>
#include <string>

namespace gsp::bench {

class Output {
 public:
  explicit Output(const std::string& path) : stdout_(path == "-") {
    if (!path.empty() && !stdout_) file_ = std::make_unique<io::AtomicFile>(path);
  }
  void write(const std::string& text) {
    if (stdout_) std::fwrite(text.data(), 1, text.size(), stdout);
    else if (file_) file_->write(text.data(), text.size()), file_->commit();
  }

 private:
  bool stdout_;
  std::unique_ptr<io::AtomicFile> file_;
};

}  // namespace gsp::bench
