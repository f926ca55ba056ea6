// -o as a shell user relies on it (issue 10, item 3): written through symbolic links (the link
// stays a link, the file it names gets the output), in place into FIFOs and devices (never
// replaced), keeping a replaced file's mode (and owner, as root), never leaving a temporary
// file or a partial output behind. Everything happens inside a private temporary directory.
// [MK89 §3.2] (the result of polygonoperation, delivered) [POSIX] (rename, symbolic links)
// Preconditions: the built mkbool (MK_CLI_EXE); POSIX (symlink, mkfifo).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "tests/cli/cli_support.hpp"

namespace mk::test {
namespace {

namespace fs = std::filesystem;

const std::string result = "POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))\n";
const std::string one_case =
    R"x({"id":1,"op":"union","a_wkt":"POLYGON((0 0,1 0,0 1,0 0))","b_wkt":"POLYGON EMPTY"})x"
    "\n";

ProcessResult run_to(const std::string& output, const std::string& b = square_b) {
  return run_mkbool({"intersection", square_a, b, "-o", output});
}

mode_t mode_of(const std::string& path) {
  struct stat st {};
  EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
  return st.st_mode & 07777;
}

bool is_symlink_to(const std::string& link, const std::string& target) {
  std::error_code ec;
  return fs::is_symlink(fs::symlink_status(link, ec)) && fs::read_symlink(link, ec) == target;
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(cliOutputFile, WritesThroughASymbolicLinkWhichStaysALink) {
  TempDir dir;
  fs::create_directory(dir.file("data"));
  const std::string real = dir.write("data/real.wkt", "old\n");
  fs::create_symlink("data/real.wkt", dir.file("link.wkt"));  // relative to the link's folder
  const ProcessResult r = run_to(dir.file("link.wkt"));
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_TRUE(is_symlink_to(dir.file("link.wkt"), "data/real.wkt"));
  EXPECT_EQ(read_text(real), result);
  EXPECT_EQ(sorted(dir.entries()), (std::vector<std::string>{"data", "link.wkt"}));
  EXPECT_EQ(fs::directory_iterator(dir.file("data"))->path().filename(), "real.wkt");  // no temporary left
}

TEST(cliOutputFile, WritesThroughAChainOfLinksAndCreatesADanglingLinksTarget) {
  TempDir dir;
  const std::string real = dir.write("real.wkt", "old\n");
  fs::create_symlink(real, dir.file("one"));
  fs::create_symlink("one", dir.file("two"));
  ASSERT_EQ(run_to(dir.file("two")).exit_code, 0);
  EXPECT_EQ(read_text(real), result);
  EXPECT_TRUE(is_symlink_to(dir.file("two"), "one"));
  EXPECT_TRUE(is_symlink_to(dir.file("one"), real));

  fs::create_symlink("new.wkt", dir.file("dangling"));
  const ProcessResult r = run_to(dir.file("dangling"));
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_TRUE(is_symlink_to(dir.file("dangling"), "new.wkt"));
  EXPECT_EQ(read_text(dir.file("new.wkt")), result);
  EXPECT_EQ(sorted(dir.entries()), (std::vector<std::string>{"dangling", "new.wkt", "one", "real.wkt", "two"}));
}

TEST(cliOutputFile, LinkLoopIsAClearError) {
  TempDir dir;
  fs::create_symlink("b", dir.file("a"));
  fs::create_symlink("a", dir.file("b"));
  const ProcessResult r = run_to(dir.file("a"));
  EXPECT_EQ(r.exit_code, 1) << describe(r);
  EXPECT_NE(r.err.find("too many levels of symbolic links"), std::string::npos) << describe(r);
  EXPECT_EQ(sorted(dir.entries()), (std::vector<std::string>{"a", "b"}));
}

TEST(cliOutputFile, ADirectoryOrAMissingDirectoryIsAClearError) {
  TempDir dir;
  fs::create_directory(dir.file("sub"));
  const ProcessResult to_dir = run_to(dir.file("sub"));
  EXPECT_EQ(to_dir.exit_code, 1) << describe(to_dir);
  EXPECT_NE(to_dir.err.find("it is a directory"), std::string::npos) << describe(to_dir);
  const ProcessResult missing = run_to(dir.file("none/out.wkt"));
  EXPECT_EQ(missing.exit_code, 1) << describe(missing);
  EXPECT_NE(missing.err.find("No such file or directory"), std::string::npos) << describe(missing);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"sub"});
  EXPECT_TRUE(fs::is_empty(dir.file("sub")));
}

TEST(cliOutputFile, AReplacedFileKeepsItsMode) {
  TempDir dir;
  for (const mode_t mode : {mode_t{0600}, mode_t{0640}, mode_t{0755}}) {
    const std::string file = dir.write("out.wkt", "old\n");
    ASSERT_EQ(::chmod(file.c_str(), mode), 0);
    ASSERT_EQ(run_to(file).exit_code, 0);
    EXPECT_EQ(read_text(file), result);
    EXPECT_EQ(mode_of(file), mode) << std::oct << mode;
  }
  // Through a link: the file it names keeps its mode.
  const std::string real = dir.write("real.wkt", "old\n");
  ASSERT_EQ(::chmod(real.c_str(), 0604), 0);
  fs::create_symlink(real, dir.file("link"));
  ASSERT_EQ(run_to(dir.file("link")).exit_code, 0);
  EXPECT_EQ(mode_of(real), mode_t{0604});
  // A new file gets what a plain open() would give: 0666 less the umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ASSERT_EQ(run_to(dir.file("new.wkt")).exit_code, 0);
  EXPECT_EQ(mode_of(dir.file("new.wkt")), 0666 & ~mask);
}

TEST(cliOutputFile, AReadOnlyFileIsNotReplacedUnlessRoot) {
  TempDir dir;
  const std::string file = dir.write("out.wkt", "old\n");
  ASSERT_EQ(::chmod(file.c_str(), 0444), 0);
  const ProcessResult r = run_to(file);
  if (::geteuid() == 0) {
    // Root may write any file, as a shell redirection would; the mode stays.
    EXPECT_EQ(r.exit_code, 0) << describe(r);
    EXPECT_EQ(read_text(file), result);
  } else {
    EXPECT_EQ(r.exit_code, 1) << describe(r);
    EXPECT_NE(r.err.find("Permission denied"), std::string::npos) << describe(r);
    EXPECT_EQ(read_text(file), "old\n");
  }
  EXPECT_EQ(mode_of(file), mode_t{0444});
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.wkt"});
}

TEST(cliOutputFile, AReplacedFileKeepsItsOwnerWhenRunAsRoot) {
  if (::geteuid() != 0) GTEST_SKIP() << "only root can give a file to another owner";
  TempDir dir;
  const std::string file = dir.write("out.wkt", "old\n");
  ASSERT_EQ(::chown(file.c_str(), 65534, 65534), 0);  // nobody:nogroup
  ASSERT_EQ(run_to(file).exit_code, 0);
  struct stat st {};
  ASSERT_EQ(::stat(file.c_str(), &st), 0);
  EXPECT_EQ(st.st_uid, 65534u);
  EXPECT_EQ(st.st_gid, 65534u);
  EXPECT_EQ(read_text(file), result);
}

// Reads a FIFO to its end on a thread, as a consumer process would.
class FifoReader {
 public:
  explicit FifoReader(const std::string& path)
      : path_(path), thread_([this, path] {
          const int fd = ::open(path.c_str(), O_RDONLY);
          if (fd < 0) return;
          char buffer[4096];
          for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) text_.append(buffer, static_cast<std::size_t>(n));
          ::close(fd);
        }) {}
  // After the writer is gone. Should it never have opened the FIFO, opening it here
  // releases the reader (which then reads nothing) instead of hanging the test.
  std::string finish() {
    const int fd = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
    thread_.join();
    return text_;
  }

 private:
  std::string path_;
  std::string text_;
  std::thread thread_;
};

TEST(cliOutputFile, AFifoIsWrittenInPlaceDirectlyOrThroughALink) {
  TempDir dir;
  const std::string fifo = dir.file("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink("pipe", dir.file("link"));
  for (const std::string& target : {fifo, dir.file("link")}) {
    FifoReader reader(fifo);
    const ProcessResult r = run_to(target);
    const std::string got = reader.finish();
    ASSERT_EQ(r.exit_code, 0) << describe(r);
    EXPECT_EQ(got, result);
    EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
    EXPECT_TRUE(is_symlink_to(dir.file("link"), "pipe"));
  }
  EXPECT_EQ(sorted(dir.entries()), (std::vector<std::string>{"link", "pipe"}));
}

TEST(cliOutputFile, ALinkToADeviceStaysALinkToTheDevice) {
  // As -o /dev/stdout did before: the link was replaced by a regular file. The link here is
  // our own; /dev/null is only written to, which is what it is for.
  TempDir dir;
  fs::create_symlink("/dev/null", dir.file("stdout"));
  for (const char* format : {"wkt", "svg"}) {
    const ProcessResult r = run_mkbool({"intersection", square_a, square_b, "--format", format, "-o", dir.file("stdout")});
    ASSERT_EQ(r.exit_code, 0) << describe(r);
    EXPECT_TRUE(is_symlink_to(dir.file("stdout"), "/dev/null"));
    EXPECT_TRUE(fs::is_character_file(fs::status(dir.file("stdout"))));
  }
  const ProcessResult batch = run_mkbool({"batch", "-", "-o", dir.file("stdout")},
                                         one_case);
  EXPECT_EQ(batch.exit_code, 0) << describe(batch);
  EXPECT_TRUE(is_symlink_to(dir.file("stdout"), "/dev/null"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"stdout"});
}

// -o /dev/stdout (or /dev/fd/N) with that stream redirected by the shell to a regular file:
// the output goes through the shell's descriptor, so `>>` appends and the file stays the
// same file. Renaming a new file over what /dev/stdout resolves to lost the earlier lines.
TEST(cliOutputFile, ARedirectedStandardStreamIsWrittenThroughTheShellsDescriptor) {
  TempDir dir;
  const std::string log = dir.write("log.txt", "earlier\n");
  struct stat before {};
  ASSERT_EQ(::stat(log.c_str(), &before), 0);
  const std::string command = "'" + mkbool_exe() + "' intersection '" + square_a + "' '" + square_b + "'";
  for (const std::string redirect : {" -o /dev/stdout >> log.txt", " -o /dev/fd/1 >> log.txt",
                                     " -o /proc/self/fd/1 >> log.txt", " -o /dev/stderr 2>> log.txt",
                                     " -o /dev/fd/3 3>> log.txt"}) {
    ProcessOptions options;
    options.cwd = dir.path().string();
    const ProcessResult r = run_process({"/bin/sh", "-c", command + redirect}, options);
    ASSERT_EQ(r.exit_code, 0) << redirect << "\n" << describe(r);
  }
  std::string expected = "earlier\n";
  for (int i = 0; i < 5; ++i) expected += result;
  EXPECT_EQ(read_text(log), expected);
  struct stat after {};
  ASSERT_EQ(::stat(log.c_str(), &after), 0);
  EXPECT_EQ(after.st_ino, before.st_ino);  // the same file, not a new one renamed over it
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"log.txt"});
}

TEST(cliOutputFile, AFailedRunLeavesTheLinkedFileAsItWas) {
  TempDir dir;
  const std::string real = dir.write("real.wkt", "old\n");
  fs::create_symlink("real.wkt", dir.file("link"));
  const ProcessResult r = run_to(dir.file("link"), "POLYGON((0 0,1 0,0 1,1 1,0 0))");  // crossing edges
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_EQ(read_text(real), "old\n");
  EXPECT_TRUE(is_symlink_to(dir.file("link"), "real.wkt"));
  EXPECT_EQ(sorted(dir.entries()), (std::vector<std::string>{"link", "real.wkt"}));
}

TEST(cliOutputFile, BatchWritesThroughALinkToo) {
  TempDir dir;
  const std::string real = dir.write("results.jsonl", "old\n");
  ASSERT_EQ(::chmod(real.c_str(), 0600), 0);
  fs::create_symlink("results.jsonl", dir.file("latest"));
  const ProcessResult r = run_mkbool({"batch", "-", "-o", dir.file("latest")},
                                     one_case);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_NE(read_text(real).find("\"area_exact\":\"1/2\""), std::string::npos) << read_text(real);
  EXPECT_TRUE(is_symlink_to(dir.file("latest"), "results.jsonl"));
  EXPECT_EQ(mode_of(real), mode_t{0600});
}

}  // namespace
}  // namespace mk::test
