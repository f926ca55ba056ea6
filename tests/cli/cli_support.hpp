// Helpers for the command's tests: run the built mkbool with a time limit, and a private
// temporary directory per test. (issue 3: the command and its bad-input suite)
// Preconditions: MK_CLI_EXE names the built command (set by tests/cli/CMakeLists.txt).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli/run_process.hpp"

namespace mk::test {

// Two overlapping squares, the command tests' usual input.
inline const std::string square_a = "POLYGON((0 0,2 0,2 2,0 2,0 0))";
inline const std::string square_b = "POLYGON((1 1,3 1,3 3,1 3,1 1))";

inline const std::string& mkbool_exe() {
  static const std::string exe = MK_CLI_EXE;
  return exe;
}

// Sanitizer builds run several times slower; the limits are for hangs, not for speed.
inline constexpr std::chrono::seconds default_limit{60};

inline ProcessResult run_mkbool(const std::vector<std::string>& args, const std::string& input = {},
                                std::chrono::milliseconds limit = default_limit, const std::string& cwd = {}) {
  std::vector<std::string> argv{mkbool_exe()};
  argv.insert(argv.end(), args.begin(), args.end());
  ProcessOptions options;
  options.input = input;
  options.limit = limit;
  options.cwd = cwd;
  return run_process(argv, options);
}

// A fresh directory under the system's temporary directory, removed with the object.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "mkbool-cli-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& content) const {
    const std::string p = file(name);
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path path_;
};

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The command's output as a shell user would report it, for failure messages.
inline std::string describe(const ProcessResult& r) {
  return "exit " + std::to_string(r.exit_code) + (r.timed_out ? " (timed out)" : "") + "\nstdout: " +
         r.out.substr(0, 2000) + "\nstderr: " + r.err.substr(0, 2000);
}

}  // namespace mk::test
