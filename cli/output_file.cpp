// Output to standard output or, atomically, to a file (temporary file, then rename).
// [MK89 §3.2]
// Preconditions: POSIX.
#include "cli/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "cli/exit_codes.hpp"

namespace mk::cli {

namespace {

std::string system_message() { return std::strerror(errno); }

void write_all(int fd, std::string_view bytes, const std::string& name) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      throw OutputError("cannot write " + name + ": " + system_message());
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

}  // namespace

OutputFile::OutputFile(std::string path) : path_(path == "-" ? std::string() : std::move(path)) {}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temporary_.empty()) ::unlink(temporary_.c_str());
}

void OutputFile::open_temporary() {
  // A device or pipe (-o /dev/null, a FIFO) is written in place: renaming a file over it
  // would replace it, and it holds no partial file anyway.
  struct stat st {};
  if (::stat(path_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    if (S_ISDIR(st.st_mode)) throw OutputError("cannot write output file '" + path_ + "': it is a directory");
    fd_ = ::open(path_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd_ < 0) throw OutputError("cannot open output '" + path_ + "': " + system_message());
    in_place_ = true;
    return;
  }
  // Same directory as the target, so that rename() stays within one file system.
  const std::filesystem::path target(path_);
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
  // Hidden, and marked as temporary, in case a crash leaves it behind.
  std::string name_in_dir(".");
  name_in_dir += target.filename().string();
  name_in_dir += ".tmp-XXXXXX";
  std::string pattern = (dir / name_in_dir).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  fd_ = ::mkstemp(name.data());
  if (fd_ < 0) throw OutputError("cannot create output file '" + path_ + "': " + system_message());
  temporary_ = name.data();
  // mkstemp creates the file private (0600); give it the mode a plain open() would.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd_, 0666 & ~mask);
}

void OutputFile::write(std::string_view bytes) {
  if (is_standard_output()) {
    write_all(STDOUT_FILENO, bytes, "standard output");
    return;
  }
  if (fd_ < 0) open_temporary();
  write_all(fd_, bytes, "'" + (in_place_ ? path_ : temporary_) + "'");
}

void OutputFile::commit() {
  if (is_standard_output()) {
    committed_ = true;
    return;
  }
  if (fd_ < 0) open_temporary();  // an empty output still replaces the target
  if (::close(fd_) != 0) {
    fd_ = -1;
    throw OutputError("cannot write '" + (in_place_ ? path_ : temporary_) + "': " + system_message());
  }
  fd_ = -1;
  if (in_place_) {
    committed_ = true;
    return;
  }
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    throw OutputError("cannot write output file '" + path_ + "': " + system_message());
  }
  committed_ = true;
}

}  // namespace mk::cli
