#pragma once
// Atomic output: everything is written to a temporary file beside the target, which replaces
// the target only when commit() is called. Destroyed without commit(), it removes the temporary.
#include <cstdio>
#include <string>

namespace gsp::io {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);   // throws gsp::IoError if the folder is not writable
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::FILE* handle() { return file_; }
  const std::string& temp_path() const { return temp_; }
  void write(const void* data, std::size_t bytes);   // throws gsp::IoError on a short write
  void commit();                                       // flush, close, rename over the target

 private:
  std::string path_, temp_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

}  // namespace gsp::io
