// Temporary file beside the target + rename(2): readers of the target see either the old file
// or the complete new one, and a failure leaves no temporary behind.
#include <gsp/io/atomic_file.hpp>

#include <gsp/errors.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

namespace gsp::io {

namespace {

// The process umask without changing it (umask(2) would race with other threads).
mode_t current_umask() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "Umask:") {
      std::string value;
      status >> value;
      return static_cast<mode_t>(std::strtol(value.c_str(), nullptr, 8));
    }
  }
  return 022;
}

std::string error_text() { return std::strerror(errno); }

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  const std::size_t slash = path_.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : path_.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? path_ : path_.substr(slash + 1);
  if (base.empty()) throw IoError(path_, "", "not a file name");
  std::string templ = dir + "." + base + ".tmp-XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  const int fd = ::mkstemp(buf.data());
  if (fd < 0) throw IoError(path_, "", "cannot create a temporary file beside it: " + error_text());
  temp_ = buf.data();
  // mkstemp creates 0600; give the result the target's mode, or what a plain create would.
  struct stat st;
  const mode_t mode = ::stat(path_.c_str(), &st) == 0 ? (st.st_mode & 07777) : (0666 & ~current_umask());
  (void)::fchmod(fd, mode);
  file_ = ::fdopen(fd, "wb");
  if (!file_) {
    const std::string why = error_text();
    ::close(fd);
    std::remove(temp_.c_str());
    throw IoError(path_, "", "cannot open the temporary file: " + why);
  }
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  if (!committed_ && !temp_.empty()) std::remove(temp_.c_str());
}

void AtomicFile::write(const void* data, std::size_t bytes) {
  if (!file_) throw IoError(path_, "", "write after commit");
  if (bytes > 0 && std::fwrite(data, 1, bytes, file_) != bytes)
    throw IoError(path_, "", "write failed: " + error_text());
}

void AtomicFile::commit() {
  if (!file_) throw IoError(path_, "", "commit called twice");
  const bool flushed = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  const std::string why = flushed ? std::string() : error_text();
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) throw IoError(path_, "", "write failed: " + (why.empty() ? error_text() : why));
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) throw IoError(path_, "", "cannot replace the file: " + error_text());
  committed_ = true;
}

}  // namespace gsp::io
