// The benchmark tools refuse bad arguments of their own as usage errors: exit 2, one line,
// before any work (issue 10, item 5: "every bad argument of every program exits 2").
// Preconditions: the built tools (paths from tests/bench/CMakeLists.txt).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/cli/run_process.hpp"

namespace mk::test {
namespace {

void expect_usage_error(const std::vector<std::string>& argv, const std::string& fragment) {
  SCOPED_TRACE(argv.front() + (argv.size() > 1 ? " " + argv[1] : ""));
  const ProcessResult r = run_process(argv);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line expected: " << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(benchArguments, PeakMemory) {
  const std::string exe = MK_PEAK_MEMORY_EXE;
  expect_usage_error({exe, "bogus"}, "unknown workload 'bogus'");
  expect_usage_error({exe, "blob", "2"}, "N must be a whole number from 3");
  expect_usage_error({exe, "blob", "-5"}, "N must be a whole number");
  expect_usage_error({exe, "blob", "10", "magic"}, "unknown kernel 'magic'");
  expect_usage_error({exe, "blob", "10", "exact", "extra"}, "unexpected argument 'extra'");
}

TEST(benchArguments, GoogleBenchmarkToolsRefuseUnknownFlags) {
  expect_usage_error({MK_BENCH_PREDICATES_EXE, "--no-such-flag"}, "unrecognized command-line flag");
#ifdef MK_BENCH_OVERLAY_EXE
  expect_usage_error({MK_BENCH_OVERLAY_EXE, "--no-such-flag"}, "unrecognized command-line flag");
#endif
}

TEST(benchArguments, GridImage) {
  expect_usage_error({MK_GRID_IMAGE_EXE}, "usage: grid_image OUT_DIR");
  expect_usage_error({MK_GRID_IMAGE_EXE, "a", "b"}, "usage: grid_image OUT_DIR");
}

}  // namespace
}  // namespace mk::test
