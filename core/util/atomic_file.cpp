// SPDX-License-Identifier: MIT
#include "util/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

std::string Describe(const fs::path& path, std::string_view problem) {
  return Quoted(path) + ": " + std::string(problem);
}

std::string ErrnoText() { return std::strerror(errno); }

// Closes the descriptor and removes the temporary file unless Release()d.
class TempFile {
 public:
  explicit TempFile(const fs::path& target) {
    std::string pattern = target.string() + ".tmp.XXXXXX";
    fd_ = ::mkstemp(pattern.data());
    if (fd_ < 0)
      throw IoError(Describe(target, "cannot create a file there (" + ErrnoText() + ")"));
    path_ = pattern;
  }
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  void CloseOrThrow(const fs::path& target) {
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw IoError(Describe(target, "close failed (" + ErrnoText() + ")"));
  }
  void Release() { path_.clear(); }

 private:
  int fd_ = -1;
  std::string path_;
};

void WriteAll(int fd, std::string_view bytes, const fs::path& target) {
  const char* data = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) throw IoError(Describe(target, "write failed (" + ErrnoText() + ")"));
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

}  // namespace

void WriteFileAtomically(const fs::path& path, std::string_view bytes) {
  TempFile temp(path);
  WriteAll(temp.fd(), bytes, path);
  if (::fsync(temp.fd()) != 0) throw IoError(Describe(path, "fsync failed (" + ErrnoText() + ")"));
  ::fchmod(temp.fd(), 0644);
  temp.CloseOrThrow(path);
  if (::rename(temp.path().c_str(), path.c_str()) != 0) {
    throw IoError(Describe(path, "cannot replace the file (" + ErrnoText() + ")"));
  }
  temp.Release();
}

std::string ReadFileBytes(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw IoError(Describe(path, "is a directory, not a file"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(Describe(path, "cannot open for reading (" + ErrnoText() + ")"));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw IoError(Describe(path, "read failed"));
  return std::move(buffer).str();
}

void CheckWritableTarget(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw IoError(Describe(path, "is a directory"));
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw IoError(Describe(path, "directory does not exist"));
  if (::access(dir.c_str(), W_OK) != 0) throw IoError(Describe(path, "directory is not writable"));
}

}  // namespace layermod
