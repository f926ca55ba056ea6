// Output to standard output or, atomically, to a file (temporary file beside the final target
// of any symbolic links, then rename); devices, FIFOs and terminals are written in place.
// [MK89 §3.2]
// Preconditions: POSIX.
#include "cli/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <climits>
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

namespace {

// Where a symbolic link chain ends when its last target does not exist yet (a dangling
// link: the output is created there, as a shell redirection would). Relative targets are
// relative to the link's directory. Throws OutputError on a loop or an unreadable link.
std::filesystem::path end_of_link_chain(const std::string& path) {
  std::filesystem::path at(path);
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(at.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return at;
    std::vector<char> target(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : PATH_MAX) + 1);
    const ssize_t n = ::readlink(at.c_str(), target.data(), target.size());
    if (n < 0) throw OutputError("cannot write output file '" + path + "': " + system_message());
    const std::filesystem::path next(std::string(target.data(), static_cast<std::size_t>(n)));
    at = next.is_absolute() ? next : at.parent_path() / next;
  }
  throw OutputError("cannot write output file '" + path + "': too many levels of symbolic links");
}

}  // namespace

void OutputFile::open_temporary() {
  // stat follows symbolic links (/dev/stdout included): what would a plain open() write to?
  struct stat st {};
  const bool exists = ::stat(path_.c_str(), &st) == 0;
  if (!exists && errno == ELOOP) {
    throw OutputError("cannot write output file '" + path_ + "': too many levels of symbolic links");
  }
  // A device, FIFO, socket or terminal (-o /dev/null, -o /dev/stdout on a pipe) is written
  // in place: renaming a file over it would replace it, and it holds no partial file anyway.
  if (exists && !S_ISREG(st.st_mode)) {
    if (S_ISDIR(st.st_mode)) throw OutputError("cannot write output file '" + path_ + "': it is a directory");
    fd_ = ::open(path_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd_ < 0) throw OutputError("cannot open output '" + path_ + "': " + system_message());
    in_place_ = true;
    return;
  }
  // A regular file, or nothing yet: the bytes go to a temporary file beside the final target
  // of any symbolic links, which is renamed over that target, so the links stay links.
  std::filesystem::path target;
  if (exists) {
    // A read-only file is not replaced behind the user's back; a shell redirection would
    // refuse it too.
    if (::access(path_.c_str(), W_OK) != 0) {
      throw OutputError("cannot write output file '" + path_ + "': " + system_message());
    }
    std::vector<char> resolved(PATH_MAX + 1);
    if (::realpath(path_.c_str(), resolved.data()) == nullptr) {
      throw OutputError("cannot write output file '" + path_ + "': " + system_message());
    }
    target = resolved.data();
  } else {
    target = end_of_link_chain(path_);
  }
  target_ = target.string();
  // Same directory as the target, so that rename() stays within one file system.
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
  if (exists) {
    // The replaced file keeps its permission bits, and its owner when we may set it (root).
    ::fchmod(fd_, st.st_mode & 07777);
    if (::geteuid() == 0) (void)!::fchown(fd_, st.st_uid, st.st_gid);
  } else {
    // mkstemp creates the file private (0600); give it the mode a plain open() would.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd_, 0666 & ~mask);
  }
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
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
    throw OutputError("cannot write output file '" + path_ + "': " + system_message());
  }
  committed_ = true;
}

}  // namespace mk::cli
