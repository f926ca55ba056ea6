// Test of experiments/slurm_sweep.sh against a stand-in for sbatch (fake_sbatch.sh) that
// runs each batch script as slurmd does, from a copy in a spool directory: the array job's
// shards and the merge job must give the results of one whole run, timings aside.
// [BRIEF §5] (sweeps split into shards for any batch scheduler)
// Preconditions: MK_EXPERIMENT_BIN names the built mkbool-experiment, MK_SOURCE_DIR the
// source tree; bash; a writable temp directory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/results.hpp"

namespace mk::experiments {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> rows_without_timings(const fs::path& dir) {
  std::vector<std::string> out;
  for (auto r : read_results_dir(dir.string())) {
    r.op_ns.reset();
    out.push_back(to_csv(r));
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Slurm, ArrayJobAndMergeGiveTheSingleRun) {
  const fs::path dir = fs::temp_directory_path() / ("mkbool_slurm_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "bin");
  fs::create_directories(dir / "spool");
  const fs::path source(MK_SOURCE_DIR);
  fs::copy_file(source / "tests/experiments/fake_sbatch.sh", dir / "bin/sbatch");
  const std::string options = " --quick --seeds 1 --generators shared_edge,identical --no-peers --no-artefacts";
  const fs::path whole = dir / "whole", sweep = dir / "sweep";
  ASSERT_EQ(std::system((std::string(MK_EXPERIMENT_BIN) + " run" + options + " --jobs 1 --no-report -o " +
                         whole.string() + " > /dev/null 2>&1")
                            .c_str()),
            0);
  // From another working directory, as a user on a login node; the binary is named by
  // MKBOOL_EXPERIMENT since this build need not be build/ of the source tree.
  const std::string submit = "cd " + dir.string() + " && PATH=" + (dir / "bin").string() +
                             ":$PATH FAKE_SBATCH_SPOOL=" + (dir / "spool").string() +
                             " MKBOOL_EXPERIMENT=" + MK_EXPERIMENT_BIN + " bash " +
                             (source / "experiments/slurm_sweep.sh").string() + " sweep 3" + options;
  std::cout << submit << "\n";
  ASSERT_EQ(std::system(submit.c_str()), 0);
  EXPECT_TRUE(fs::exists(sweep / "README.md"));
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(fs::exists(sweep / "shards" / ("results-shard-" + std::to_string(i) + "-of-3.csv"))) << i;
  }
  const auto a = rows_without_timings(whole);
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, rows_without_timings(sweep));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mk::experiments
