// mkbool-experiment refuses every bad argument as a usage error: exit 2, one line naming the
// argument and what it expects, before any work or any file is made (issue 10, item 5).
// Preconditions: MK_EXPERIMENT_BIN names the built mkbool-experiment; a writable temp directory.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli/run_process.hpp"

namespace mk::test {
namespace {

namespace fs = std::filesystem;

struct BadArguments {
  std::vector<std::string> args;
  std::string fragment;
};

TEST(experimentsArguments, EveryBadArgumentExitsTwoWithOneLine) {
  const fs::path dir = fs::temp_directory_path() / ("mkbool-experiment-args-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "empty");
  const std::string out = (dir / "out").string();
  const std::string empty = (dir / "empty").string();
  const std::vector<BadArguments> cases = {
      {{}, "A subcommand is required"},
      {{"bogus"}, "unknown command 'bogus'"},
      {{"run"}, "--out is required"},
      {{"run", "--kernels", "bogus", "-o", out}, "--kernels: unknown kernel 'bogus'"},
      {{"run", "--kernels", "exact,bogus", "-o", out}, "unknown kernel 'bogus'"},
      {{"run", "--generators", "nosuch", "-o", out}, "--generators: unknown generator 'nosuch'"},
      {{"run", "--seeds", "0", "-o", out}, "--seeds: expected a whole number of seeds from 1 to 1000000, got '0'"},
      {{"run", "--seeds", "1e3", "-o", out}, "got '1e3'"},
      {{"run", "--seed", "-5", "-o", out}, "--seed: expected a whole number from 0 to 2^64-1, got '-5'"},
      {{"run", "--seed", "18446744073709551616", "-o", out}, "got '18446744073709551616'"},
      {{"run", "--shard", "3/2", "-o", out}, "--shard: shard must be i/N with 0 <= i < N"},
      {{"run", "--jobs", "0", "-o", out}, "--jobs: expected a whole number of worker processes"},
      {{"run", "--timeout", "-1", "-o", out}, "--timeout: expected a positive number of seconds, got '-1'"},
      {{"run", "--timeout", "nan", "-o", out}, "got 'nan'"},
      {{"run", "--memory-mb", "-5", "-o", out}, "--memory-mb: expected a whole number of megabytes"},
      {{"run", "--quick", "--full", "-o", out}, "excludes"},
      {{"case", "--generator", "nosuch", "--variant", "a", "--seed", "1"}, "unknown generator 'nosuch'"},
      {{"case", "--generator", "shared_vertex", "--variant", "nosuch", "--seed", "1"},
       "--variant: generator shared_vertex has no variant 'nosuch'"},
      {{"case", "--generator", "shared_vertex", "--variant", "outside", "--seed", "-1"}, "--seed: expected"},
      {{"case", "--generator", "shared_vertex", "--variant", "outside", "--seed", "1", "--op", "bogus"},
       "--op: unknown operation 'bogus'"},
      {{"case", "--generator", "shared_vertex", "--variant", "outside", "--seed", "1", "--params", "zz"},
       "--params: bad parameter 'zz'"},
      {{"merge", (dir / "nonexistent").string()}, "Directory does not exist"},
      {{"merge", empty}, "none of the directories holds results*.csv"},
      {{"report", empty}, "holds no results*.csv"},
      {{"list", "extra"}, "was not expected: extra"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> argv{MK_EXPERIMENT_BIN};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    std::string shown;
    for (const auto& a : c.args) shown += " " + a;
    SCOPED_TRACE("mkbool-experiment" + shown);
    ProcessOptions options;
    options.limit = std::chrono::seconds(60);
    const ProcessResult r = run_process(argv, options);
    ASSERT_FALSE(r.timed_out);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("mkbool-experiment: error: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line expected: " << r.err;
    EXPECT_NE(r.err.find(c.fragment), std::string::npos) << r.err;
    EXPECT_LT(r.err.size(), 400u) << r.err;  // no 300-digit ranges
  }
  EXPECT_FALSE(fs::exists(out)) << "a refused run made its output directory";
  EXPECT_TRUE(fs::is_empty(empty));  // report and merge wrote nothing into it
  fs::remove_all(dir);
}

TEST(experimentsArguments, SymdifferenceIsAcceptedWhereAnOperationIsNamed) {
  const fs::path dir = fs::temp_directory_path() / ("mkbool-experiment-sym-" + std::to_string(::getpid()));
  const ProcessResult r = run_process({MK_EXPERIMENT_BIN, "case", "--generator", "shared_vertex", "--variant",
                                       "outside", "--seed", "1", "--op", "symdifference", "-o", dir.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("_xor.wkt"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mk::test
