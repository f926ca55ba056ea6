// Every example of docs/usage.md runs as written, from the repository root, and prints what
// the page shows; the page's C++ example is the source of examples/consumer. (issue 3:
// "a new user can run every example in the README's usage section as written")
// Preconditions: the built mkbool (MK_CLI_EXE); MK_SOURCE_DIR is the repository root.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"

namespace mk::test {
namespace {

struct Example {
  int line = 0;  // of the command in docs/usage.md
  std::string command;
  std::string expected;
};

// ```console blocks: a line starting with "$ " is a command (a trailing backslash continues
// it), the lines up to the next command or the block's end are its output.
std::vector<Example> console_examples(const std::string& markdown) {
  std::vector<Example> examples;
  std::istringstream in(markdown);
  bool in_console = false;
  bool in_other = false;
  bool continued = false;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.rfind("```", 0) == 0) {
      if (in_console || in_other) {
        in_console = in_other = false;
      } else {
        (line == "```console" ? in_console : in_other) = true;
      }
      continue;
    }
    if (!in_console) continue;
    if (continued) {
      examples.back().command += "\n" + line;
      continued = !line.empty() && line.back() == '\\';
    } else if (line.rfind("$ ", 0) == 0) {
      examples.push_back({number, line.substr(2), ""});
      continued = !line.empty() && line.back() == '\\';
    } else if (!examples.empty()) {
      examples.back().expected += line + "\n";
    }
  }
  return examples;
}

std::string fenced_block(const std::string& markdown, const std::string& language) {
  const std::string open = "```" + language + "\n";
  const auto start = markdown.find(open);
  if (start == std::string::npos) return {};
  const auto body = start + open.size();
  return markdown.substr(body, markdown.find("```\n", body) - body);
}

// Timings differ from run to run: the digits after "op_ns": become N. (Not std::regex: GCC
// 12 warns inside it under the sanitizers, and warnings are errors in CI.)
std::string without_timings(const std::string& s) {
  constexpr std::string_view key = "\"op_ns\":";
  std::string out;
  std::size_t from = 0;
  for (auto at = s.find(key); at != std::string::npos; at = s.find(key, from)) {
    std::size_t end = at + key.size();
    while (end < s.size() && s[end] >= '0' && s[end] <= '9') ++end;
    out.append(s, from, at + key.size() - from);
    out += 'N';
    from = end;
  }
  out.append(s, from, std::string::npos);
  return out;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
  return s;
}

const std::string usage_md = read_text(std::string(MK_SOURCE_DIR) + "/docs/usage.md");

TEST(cliUsageDoc, EveryConsoleExampleRunsAsWritten) {
  const auto examples = console_examples(usage_md);
  ASSERT_GE(examples.size(), 10u) << "docs/usage.md lost its examples";
  for (const auto& e : examples) {
    SCOPED_TRACE("docs/usage.md:" + std::to_string(e.line) + ": $ " + e.command);
    ASSERT_NE(e.command.find("build/bin/mkbool"), std::string::npos);
    ProcessOptions options;
    options.cwd = MK_SOURCE_DIR;
    options.merge_stderr = true;
    const ProcessResult r =
        run_process({"/bin/sh", "-c", replace_all(e.command, "build/bin/mkbool", mkbool_exe())}, options);
    ASSERT_FALSE(r.timed_out);
    // A failure must be shown as one: the example then ends in `; echo "exit $?"`.
    if (e.command.find("echo \"exit $?\"") == std::string::npos) {
      EXPECT_EQ(r.exit_code, 0) << r.out;
    }
    EXPECT_EQ(without_timings(r.out), without_timings(e.expected));
  }
}

TEST(cliUsageDoc, LibraryExampleIsTheConsumerProject) {
  const std::string shown = fenced_block(usage_md, "cpp");
  ASSERT_FALSE(shown.empty());
  EXPECT_EQ(shown, read_text(std::string(MK_SOURCE_DIR) + "/examples/consumer/main.cpp"));
  const std::string cmake = fenced_block(usage_md, "cmake");
  ASSERT_FALSE(cmake.empty());
  EXPECT_EQ(cmake, read_text(std::string(MK_SOURCE_DIR) + "/examples/consumer/CMakeLists.txt"));
}

}  // namespace
}  // namespace mk::test
