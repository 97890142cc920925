// AtomicFile: write an output file under a temporary name in the same folder and
// rename it into place only when it is complete.
//
// CONVENTIONS.md promises that an error never leaves a partial output behind and that
// the other files of an existing output folder are untouched. rename(2) within one
// file system is atomic, so readers see either the old file or the whole new one.
// The temporary name starts with '.' and ends in ".tmp-PID-N" so that a leftover from
// a killed process is hidden, recognisable, and never collides with a live writer.
//
// Every failure throws scallop::InputError whose `where` is the *final* path and whose
// message carries the operating system's reason (strerror), e.g.
//   "out/heights.exr: cannot create temporary file out/.heights.exr.tmp-42-0: Permission denied"
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace scallop {

class AtomicFile {
 public:
  AtomicFile() = default;
  explicit AtomicFile(const std::string& path) { open(path); }
  // Removes the temporary file unless commit() succeeded.
  ~AtomicFile();

  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Creates an empty temporary file next to `path` and returns its name; the caller
  // (or a library such as OpenImageIO) then writes the whole content to it. Creating
  // it here reports a missing or read-only folder with the OS reason, before any
  // expensive work. Throws InputError(path, ...) on failure.
  const std::string& open(const std::string& path);

  // Flushes the temporary file to disk and renames it to the final path, replacing
  // any existing file there. On failure the temporary file is removed and
  // InputError(path, ...) is thrown.
  void commit();

  // Removes the temporary file now (also done by the destructor). Never throws.
  void discard() noexcept;

  const std::string& path() const { return path_; }
  const std::string& tempPath() const { return tempPath_; }
  bool isOpen() const { return !tempPath_.empty(); }

 private:
  std::string path_;
  std::string tempPath_;  // empty when nothing is pending
};

// Runs `writer(tempPath)` and commits the result to `path`. If the writer throws, the
// temporary file is removed and the exception propagates unchanged.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tempPath)>& writer);

// The common case of writeFileAtomically: `fill` writes the whole content to a binary
// stream on the temporary file. A stream left failed (disk full, I/O error) throws
// InputError(path, "cannot write " + what), and the temporary file is removed.
void writeStreamAtomically(const std::string& path, const std::string& what,
                           const std::function<void(std::ostream& out)>& fill);

// Writes `text` as the whole content of `path`, atomically.
void writeTextAtomically(const std::string& path, const std::string& text, const std::string& what);

// True when `name` (a file name without folder) has the form of a temporary that
// AtomicFile creates for the file named `finalName`: ".FINALNAME.tmp-PID-N". Used to
// find what a killed process left (band_files.h); says nothing about whether its
// writer is still alive.
bool isTemporaryNameOf(const std::string& name, const std::string& finalName);

// Creates `dir` (and missing parents) if needed and checks that files can be created
// in it by creating and removing a probe file. Throws InputError(dir, reason) when it
// cannot be created, is not a folder, or is not writable.
void ensureWritableDirectory(const std::string& dir);

}  // namespace scallop
