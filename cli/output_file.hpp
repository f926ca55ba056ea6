// Writing the command's output to standard output or, all or nothing, to a named file.
// [MK89 §3.2] (the result of polygonoperation, delivered to the user)
// Preconditions: POSIX (mkstemp, rename); the target's directory exists and is writable.
#pragma once

#include <string>
#include <string_view>

namespace mk::cli {

// With a path, the bytes go to a temporary file in the target's directory, which commit()
// renames over the target: rename within one file system is atomic, so a reader (or a
// failed run) never sees a partial file and an older file stays intact until the end.
// Without commit() the destructor removes the temporary file. A symbolic link is written
// through: the target is the link chain's final file (created if the link dangles), so the
// link stays a link. A replaced file keeps its permission bits (and, run as root, its
// owner); a read-only file is refused. An empty path or `-` means standard output, written
// as it comes; a target that is not a regular file (a device such as /dev/null, a FIFO, a
// terminal, /dev/stdout on a pipe) is written in place, never replaced. Hard links to a
// replaced file keep the old contents, as with any rename-based writer.
// Failures throw mk::cli::OutputError.
class OutputFile {
 public:
  explicit OutputFile(std::string path);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();

  void write(std::string_view bytes);
  void commit();

 private:
  bool is_standard_output() const { return path_.empty(); }
  void open_temporary();

  std::string path_;       // empty: standard output
  std::string target_;     // the file renamed over: path_ with its symbolic links resolved
  std::string temporary_;  // created on the first write
  int fd_ = -1;
  bool in_place_ = false;  // the target is a device or pipe, written directly
  bool committed_ = false;
};

}  // namespace mk::cli
