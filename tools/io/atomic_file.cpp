#include "tools/io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "base/input_error.h"
#include "base/internal_error.h"

namespace scallop {

namespace fs = std::filesystem;

namespace {

std::string osReason(int err) {
  return std::strerror(err);
}

// A process-wide counter keeps two AtomicFiles for the same path (e.g. from two
// threads) from sharing a temporary name.
std::atomic<unsigned> tempCounter{0};

// The temporary name's parts around PID and N; isTemporaryNameOf reads them back.
constexpr const char* kTempInfix = ".tmp-";

std::string tempNameFor(const std::string& path) {
  const fs::path p(path);
  const std::string name = "." + p.filename().string() + kTempInfix + std::to_string(::getpid()) +
                           "-" + std::to_string(tempCounter.fetch_add(1));
  return (p.parent_path() / name).string();
}

// True when `text` from `pos` is one or more decimal digits ending at `end`.
bool digitsBetween(const std::string& text, size_t pos, size_t end) {
  if (pos >= end) return false;
  for (size_t i = pos; i < end; ++i)
    if (text[i] < '0' || text[i] > '9') return false;
  return true;
}

// Writes the file's data to stable storage so that a crash just after the rename
// cannot expose an empty file under the final name.
int syncFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int rc = ::fsync(fd);
  const int err = rc == 0 ? 0 : errno;
  ::close(fd);
  // File systems that cannot sync (some FUSE mounts) return EINVAL; the data is
  // still complete, so only real I/O errors count.
  return err == EINVAL ? 0 : err;
}

}  // namespace

AtomicFile::~AtomicFile() {
  discard();
}

const std::string& AtomicFile::open(const std::string& path) {
  discard();
  if (path.empty() || fs::path(path).filename().empty())
    throw InputError(path, "not a file name (it is empty or ends in a path separator)");
  path_ = path;
  const std::string temp = tempNameFor(path);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int err = errno;
    throw InputError(path, "cannot create temporary file " + temp + ": " + osReason(err));
  }
  ::close(fd);
  tempPath_ = temp;
  return tempPath_;
}

void AtomicFile::commit() {
  if (tempPath_.empty()) throw InternalError(path_ + ": commit() without a pending temporary file");
  if (const int err = syncFile(tempPath_)) {
    discard();
    throw InputError(path_, "cannot flush the temporary file to disk: " + osReason(err));
  }
  if (std::rename(tempPath_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    discard();
    throw InputError(path_,
                     "cannot rename the finished temporary file into place: " + osReason(err));
  }
  tempPath_.clear();
}

void AtomicFile::discard() noexcept {
  if (tempPath_.empty()) return;
  ::unlink(tempPath_.c_str());
  tempPath_.clear();
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tempPath)>& writer) {
  AtomicFile file(path);
  writer(file.tempPath());
  file.commit();
}

void writeStreamAtomically(const std::string& path, const std::string& what,
                           const std::function<void(std::ostream& out)>& fill) {
  writeFileAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    fill(out);
    if (!out.flush()) throw InputError(path, "cannot write " + what);
  });
}

void writeTextAtomically(const std::string& path, const std::string& text,
                         const std::string& what) {
  writeStreamAtomically(path, what, [&](std::ostream& out) { out << text; });
}

bool isTemporaryNameOf(const std::string& name, const std::string& finalName) {
  const std::string prefix = "." + finalName + kTempInfix;
  if (finalName.empty() || name.compare(0, prefix.size(), prefix) != 0) return false;
  const size_t dash = name.find('-', prefix.size());
  return dash != std::string::npos && digitsBetween(name, prefix.size(), dash) &&
         digitsBetween(name, dash + 1, name.size());
}

void ensureWritableDirectory(const std::string& dir) {
  if (dir.empty()) throw InputError(dir, "output folder name is empty");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(dir, "exists but is not a folder");
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir, "cannot create output folder: " + ec.message());

  // Permission bits do not tell the whole story (read-only mounts, ACLs, root), so
  // try what we are going to do: create a file and remove it.
  const std::string probe =
      (fs::path(dir) / (".scallop-probe-" + std::to_string(::getpid()))).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int err = errno;
    throw InputError(dir, "cannot create files in output folder: " + osReason(err));
  }
  ::close(fd);
  if (::unlink(probe.c_str()) != 0) {
    const int err = errno;
    throw InputError(dir, "cannot remove files in output folder: " + osReason(err));
  }
}

}  // namespace scallop
