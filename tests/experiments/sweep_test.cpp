// Tests of the sweep: a tiny sweep through the library and through the mkbool-experiment
// binary (CSV with the documented columns, the report, exact kernels only exact_match),
// the user's own cases (run --cases, case --generator cases), and the worker pool's survival
// of a crashing and a hanging run. [MK89 §3.3]
// Preconditions: MK_EXPERIMENT_BIN names the built mkbool-experiment; a writable temp directory.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "api/mkbool.hpp"
#include "experiments/artefacts.hpp"
#include "experiments/generators.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/report.hpp"
#include "experiments/runner.hpp"

namespace mk::experiments {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> all_kernels() {
  std::vector<std::string> out;
  for (const auto k : kernel_names()) out.emplace_back(k);
  return out;
}

void expect_exact_kernels_match(const std::vector<ResultRow>& rows) {
  for (const auto& r : rows) {
    if (r.kernel == "reference" || is_exact_kernel(r.kernel)) {
      EXPECT_EQ(r.verdict, Verdict::exact_match) << to_csv(r);
    }
  }
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("mkbool_experiments_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(Sweep, TinySweepInProcess) {
  const auto plan = plan_sweep({SweepLevel::quick, 1, 5, {"shared_edge", "ulp_perturbed", "paper_figures"}});
  RunOptions o;
  o.kernels = all_kernels();
  o.isolate = false;
  SweepStats stats;
  const auto rows = run_sweep(select_shard(plan, {}), o, "", &stats);
  EXPECT_EQ(rows.size(), plan.size() * 8 * o.kernels.size());
  expect_exact_kernels_match(rows);
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_LE(rows[i - 1].case_index, rows[i].case_index);
}

// --grid: every bounded result of an exact kernel is snapped onto the user's grid and
// written valid, and verdicts still compare the exact results; --rounding nearest leaves
// the nearest doubles and never snaps.
TEST(Sweep, RoundingOptionsReachEveryRun) {
  const auto plan = plan_sweep({SweepLevel::quick, 1, 3, {"shared_edge", "ulp_perturbed"}});
  RunOptions o;
  o.kernels = {"exact", "rational"};
  o.isolate = false;
  o.grid = "0.001";  // not a power of two: its points are not all doubles
  const auto snapped = run_sweep(select_shard(plan, {}), o, "");
  ASSERT_FALSE(snapped.empty());
  std::size_t bounded = 0;
  for (const auto& r : snapped) {
    if (r.kernel == "reference" || !r.certified_snapped) continue;
    ++bounded;
    EXPECT_EQ(r.certified_snapped, true) << to_csv(r);
    EXPECT_EQ(r.certified_valid, true) << to_csv(r);
  }
  EXPECT_GT(bounded, snapped.size() / 4);
  expect_exact_kernels_match(snapped);
  o.grid.clear();
  o.rounding = RoundingMode::nearest;
  for (const auto& r : run_sweep(select_shard(plan, {}), o, "")) {
    if (r.certified_snapped) {
      EXPECT_EQ(*r.certified_snapped, false) << to_csv(r);
    }
  }
}

TEST(Sweep, ACrashAndAHangCostOneRunEach) {
  const auto plan = plan_sweep({SweepLevel::quick, 1, 1, {"shared_edge"}});
  ASSERT_GE(plan.size(), 2u);
  RunOptions o;
  o.kernels = all_kernels();
  o.ops = {Operation::intersection};
  o.regular = {true};
  o.jobs = 2;
  o.timeout_seconds = 1;
  const std::string victim = o.kernels.back();
  o.fault_injection = [&](const std::string& kernel, const CaseSpec& spec) {
    if (kernel != victim) return;
    if (spec.seed == plan[0].seed) std::abort();  // a failed assertion, say
    if (spec.seed == plan[1].seed) std::this_thread::sleep_for(std::chrono::seconds(30));
  };
  const auto rows = run_sweep(select_shard(plan, {}), o, "");
  ASSERT_EQ(rows.size(), plan.size() * o.kernels.size());  // every run has its row
  for (const auto& r : rows) {
    if (r.kernel != victim || r.case_index > 1) {
      if (is_exact_kernel(r.kernel)) {
        EXPECT_EQ(r.verdict, Verdict::exact_match) << to_csv(r);
      }
      continue;
    }
    EXPECT_EQ(r.verdict, r.case_index == 0 ? Verdict::crash : Verdict::timeout) << to_csv(r);
    EXPECT_EQ(r.seed, plan[r.case_index].seed);
    EXPECT_GT(r.size, 0u);
  }
}

TEST(Sweep, ExactKernelFailuresBecomeRegressionCasesAndPictures) {
  // A made-up failure of the rational kernel and a real-looking one of double.
  const CaseSpec spec{"vertex_on_edge", "crossing", {}, 42};
  ResultRow r;
  r.case_index = 3;
  r.generator = spec.generator;
  r.variant = spec.variant;
  r.seed = spec.seed;
  r.size = make_case(spec).size();
  r.op = "union";
  r.regular = false;
  r.kernel = "rational";
  r.verdict = Verdict::valid_different;
  ResultRow d = r;
  d.kernel = "double";
  d.verdict = Verdict::invalid_output;
  const fs::path dir = fresh_dir("artefacts");
  const auto arts = write_artefacts({r, d}, dir.string(), {});
  const fs::path wkt = dir / "regression" / "vertex_on_edge_42.wkt";
  ASSERT_TRUE(fs::exists(wkt));
  std::ifstream in(wkt);
  const RegressionCase c = read_regression_case(std::string((std::istreambuf_iterator<char>(in)), {}));
  const Case original = make_case(spec);
  EXPECT_EQ(c.op, Operation::union_);
  EXPECT_FALSE(c.regular);
  EXPECT_EQ(c.a.rings.size(), original.a.rings.size());
  EXPECT_EQ(c.b.rings.size(), original.b.rings.size());
  std::size_t pictures = 0;
  for (const auto& a : arts) {
    if (a.kind == Artefact::Kind::picture) {
      ++pictures;
      EXPECT_TRUE(fs::exists(dir / a.path)) << a.path;
    }
  }
  EXPECT_EQ(pictures, 2u);  // the rational failure and the double one
  EXPECT_EQ(read_artefacts(dir.string()).size(), arts.size());
  fs::remove_all(dir);
}

int run(const std::string& args) {
  const std::string cmd = std::string(MK_EXPERIMENT_BIN) + " " + args + " > /dev/null 2>&1";
  return std::system(cmd.c_str());
}

TEST(Sweep, BinaryWritesTheCsvAndTheReport) {
  const fs::path dir = fresh_dir("binary");
  ASSERT_EQ(run("run --quick --seeds 1 --generators shared_edge,ulp_perturbed,kettner_grid -o " + dir.string()), 0);
  std::ifstream csv(dir / "results.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, csv_header());
  const auto rows = read_results_dir(dir.string());
  EXPECT_FALSE(rows.empty());
  std::set<std::string> kernels;
  for (const auto& r : rows) kernels.insert(r.kernel);
  // Every kernel but the number-type variants of `rational`, which only --full runs by default.
  for (const auto k : kernel_names()) {
    EXPECT_EQ(kernels.count(std::string(k)), is_number_type_variant(k) ? 0u : 1u) << "kernel " << k;
  }
  expect_exact_kernels_match(rows);
  ASSERT_TRUE(fs::exists(dir / "README.md"));
  std::ifstream md(dir / "README.md");
  const std::string text((std::istreambuf_iterator<char>(md)), {});
  EXPECT_NE(text.find("## Verdicts per kernel"), std::string::npos);
  EXPECT_NE(text.find("## Time relative to `double`"), std::string::npos);
  if (fs::exists("/usr/bin/python3") && std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") == 0) {
    EXPECT_TRUE(fs::exists(dir / "plots" / "failure_vs_ulps.png"));
    EXPECT_NE(text.find("plots/failure_vs_ulps.png"), std::string::npos);
  }
  // Results that certified rounding snapped (ulp_perturbed, kettner_grid) are pictured.
  const auto snapped = std::count_if(rows.begin(), rows.end(), [](const ResultRow& r) {
    return r.kernel == "exact" && r.certified_snapped == true;
  });
  EXPECT_GT(snapped, 0);
  std::size_t pictures = 0;
  for (const auto& a : read_artefacts(dir.string())) {
    if (a.kind != Artefact::Kind::snapping) continue;
    ++pictures;
    EXPECT_TRUE(fs::exists(dir / a.path)) << a.path;
    EXPECT_NE(text.find("](" + a.path + ")"), std::string::npos) << a.path;
  }
  EXPECT_GT(pictures, 0u);
  // The report regenerates from the CSV alone, with the pictures of snapped results.
  fs::remove(dir / "README.md");
  ASSERT_EQ(run("report --no-plots " + dir.string()), 0);
  EXPECT_TRUE(fs::exists(dir / "README.md"));
  std::ifstream again(dir / "README.md");
  const std::string regenerated((std::istreambuf_iterator<char>(again)), {});
  EXPECT_NE(regenerated.find("](pictures/snapping/"), std::string::npos);
  fs::remove_all(dir);
}

TEST(Sweep, NoArtefactsMeansNoPicturesOfSnappedResults) {
  const fs::path dir = fresh_dir("no_artefacts");
  ASSERT_EQ(run("run --quick --seeds 1 --generators ulp_perturbed --kernels exact --no-artefacts --no-plots -o " +
                dir.string()),
            0);
  const auto rows = read_results_dir(dir.string());
  EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [](const ResultRow& r) { return r.certified_snapped == true; }));
  EXPECT_FALSE(fs::exists(dir / "pictures"));
  EXPECT_TRUE(read_artefacts(dir.string()).empty());
  fs::remove_all(dir);
}

TEST(Sweep, UserCasesRunEveryBackEndAndBecomeRegressionCasesInOneStep) {
  // experiments/README.md, "Your own cases": run --cases sweeps the user's pairs through
  // every back end; case --generator cases writes one as a regression case file.
  const fs::path dir = fresh_dir("user_cases");
  const fs::path file = dir / "prod.jsonl";
  std::ofstream(file) << R"J({"id":"overlap","op":"union","a_wkt":"POLYGON((0 0,2 0,2 2,0 2,0 0))",)J"
                      << R"J("b_wkt":"POLYGON((1 1,3 1,3 3,1 3,1 1))","note":"ignored"})J" "\n"
                      << R"J({"op":"difference","a_wkt":"POLYGON((0 0,4 0,4 4,0 4,0 0))",)J"
                      << R"J("b_wkt":"POLYGON((4 1,6 1,6 3,4 3,4 1))"})J" "\n";
  const fs::path out = dir / "out";
  ASSERT_EQ(run("run --cases " + file.string() + " --jobs 1 --no-artefacts --no-plots -o " + out.string()), 0);
  const auto rows = read_results_dir(out.string());
  std::set<std::string> variants, back_ends;
  for (const auto& r : rows) {
    EXPECT_EQ(r.generator, "cases") << to_csv(r);
    variants.insert(r.variant);
    back_ends.insert(r.kernel);
  }
  EXPECT_EQ(variants, (std::set<std::string>{"overlap", "line2"}));
  for (const auto k : kernel_names()) EXPECT_EQ(back_ends.count(std::string(k)), is_number_type_variant(k) ? 0u : 1u) << k;
  for (const auto p : peer_names()) EXPECT_EQ(back_ends.count(std::string(p)), 1u) << p;
  expect_exact_kernels_match(rows);
  std::ifstream md(out / "README.md");
  const std::string text((std::istreambuf_iterator<char>(md)), {});
  EXPECT_NE(text.find("| overlap |"), std::string::npos);

  const fs::path reg = dir / "regression";
  ASSERT_EQ(run("case --generator cases --cases " + file.string() + " --variant overlap --op union --no-pictures -o " +
                reg.string()),
            0);
  std::ifstream in(reg / "cases_overlap_union.wkt");
  ASSERT_TRUE(in) << "no regression case file written";
  const std::string written((std::istreambuf_iterator<char>(in)), {});
  const RegressionCase c = read_regression_case(written);
  EXPECT_EQ(c.op, Operation::union_);
  EXPECT_TRUE(c.regular);
  EXPECT_EQ(c.a.rings.size(), 1u);
  EXPECT_EQ(c.b.rings.size(), 1u);
  EXPECT_EQ(c.a.rings[0].size() + c.b.rings[0].size(), 8u);
  fs::remove_all(dir);
}

// The first line of a shell command's output ("" when it fails).
std::string output_of(const std::string& command) {
  std::string out;
  if (FILE* f = ::popen(command.c_str(), "r")) {
    char buf[256];
    if (std::fgets(buf, sizeof buf, f)) out = buf;
    ::pclose(f);
  }
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

TEST(Sweep, SweepTxtNamesTheCommitTheBinaryWasBuiltFrom) {
  // Issue 15: sweep.txt records the commit. It must be the build's, known without asking git
  // at run time: here git cannot find the tree when the sweep runs (GIT_DIR points nowhere).
  const fs::path dir = fresh_dir("commit");
  ASSERT_EQ(std::system(("GIT_DIR=/nonexistent " + std::string(MK_EXPERIMENT_BIN) +
                         " run --quick --seeds 1 --generators identical --no-peers --no-artefacts --no-report -o " +
                         dir.string() + " > /dev/null 2>&1")
                            .c_str()),
            0);
  std::ifstream in(dir / "sweep.txt");
  std::string line, commit_line;
  while (std::getline(in, line)) {
    if (line.rfind("commit: ", 0) == 0) commit_line = line;
  }
  const std::string head = output_of("git -C '" MK_SOURCE_DIR "' rev-parse --short=12 HEAD 2>/dev/null");
  std::cout << commit_line << " (source tree HEAD: " << (head.empty() ? "none" : head) << ")\n";
  if (head.empty()) {
    EXPECT_EQ(commit_line, "commit: unknown (not a git checkout)");
  } else {
    EXPECT_EQ(commit_line.rfind("commit: " + head, 0), 0u) << commit_line;
  }
  fs::remove_all(dir);
}

TEST(Sweep, ShardsMergeIntoTheWholeSweep) {
  const fs::path dir = fresh_dir("shards");
  const std::string common = "run --quick --seeds 1 --generators shared_vertex,identical --no-artefacts -o ";
  const fs::path whole = dir / "whole", parts = dir / "parts";
  ASSERT_EQ(run(common + whole.string() + " --no-plots"), 0);
  ASSERT_EQ(run(common + parts.string() + " --shard 0/2"), 0);
  ASSERT_EQ(run(common + parts.string() + " --shard 1/2"), 0);
  ASSERT_EQ(run("merge --no-plots " + parts.string()), 0);
  const auto a = read_results_dir(whole.string());
  const auto b = read_results_dir(parts.string());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].case_index, b[i].case_index);
    EXPECT_EQ(a[i].seed, b[i].seed);
    EXPECT_EQ(a[i].kernel, b[i].kernel);
    EXPECT_EQ(a[i].verdict, b[i].verdict);
  }
  EXPECT_TRUE(fs::exists(parts / "README.md"));
  EXPECT_NE(run("run --shard 2/2 -o " + dir.string()), 0);  // bad arguments fail
  fs::remove_all(dir);
}

// The rows of a sweep as CSV lines without the one column that measures time.
std::vector<std::string> without_timings(std::vector<ResultRow> rows) {
  std::vector<std::string> out;
  for (auto& r : rows) {
    r.op_ns.reset();
    out.push_back(to_csv(r));
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Sweep, ConcurrentShardsMergeIntoTheSingleRunTimingsAside) {
  // N shard processes at the same time writing into one directory, as array tasks do on a
  // shared filesystem; their merge must equal one whole run, every column but op_ns.
  const fs::path dir = fresh_dir("concurrent");
  const std::string common = std::string(MK_EXPERIMENT_BIN) +
                             " run --quick --seeds 1 --generators shared_edge,hole_filled,reported --jobs 1 --no-artefacts";
  const fs::path whole = dir / "whole", parts = dir / "parts";
  ASSERT_EQ(run("run --quick --seeds 1 --generators shared_edge,hole_filled,reported --jobs 2 --no-artefacts --no-report -o " +
                whole.string()),
            0);
  constexpr int shards = 3;
  std::string script = "(";
  for (int i = 0; i < shards; ++i) {
    script += common + " --shard " + std::to_string(i) + "/" + std::to_string(shards) + " -o " + parts.string() +
              " > /dev/null 2>&1; echo $? > " + (dir / ("rc" + std::to_string(i))).string() + ") & (";
  }
  script += "true); wait";
  ASSERT_EQ(std::system(("bash -c '" + script + "'").c_str()), 0);
  for (int i = 0; i < shards; ++i) {
    std::ifstream rc(dir / ("rc" + std::to_string(i)));
    int code = -1;
    rc >> code;
    EXPECT_EQ(code, 0) << "shard " << i;
  }
  ASSERT_EQ(run("merge --no-plots " + parts.string()), 0);
  const auto a = read_results_dir(whole.string());
  const auto b = read_results_dir(parts.string());
  ASSERT_FALSE(a.empty());
  std::set<std::string> kernels;
  for (const auto& r : a) kernels.insert(r.kernel);
  for (const auto p : peer_names()) EXPECT_TRUE(kernels.count(std::string(p))) << "peer " << p << " missing";
  EXPECT_EQ(without_timings(a), without_timings(b));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mk::experiments
