// mkbool-experiment: run robustness sweeps (generators x kernels x operations x regular x
// seeds), merge shards, write the report, and reproduce single cases. [MK89 §3.3]
// Preconditions: none; bad arguments exit with status 2 and a message.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <thread>

#include "api/mkbool.hpp"
#include "experiments/artefacts.hpp"
#include "experiments/generators.hpp"
#include "experiments/report.hpp"
#include "experiments/runner.hpp"

namespace fs = std::filesystem;
using namespace mk::experiments;

namespace {

struct RunArgs {
  bool quick = false, full = false;
  std::vector<std::string> kernels, generators;
  int seeds = 0;
  std::uint64_t base_seed = 1;
  std::string shard;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  double timeout = 0;
  std::size_t memory_mb = 0;
  bool no_artefacts = false, no_report = false, no_plots = false;
  std::string out;
};

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&t));
  return buf;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool address_sanitizer = true;
#elif defined(__has_feature)
constexpr bool address_sanitizer = __has_feature(address_sanitizer);
#else
constexpr bool address_sanitizer = false;
#endif

std::size_t default_memory_mb(int jobs) {
  if (address_sanitizer) return 0;  // it reserves terabytes of address space: no limit fits
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return 0;
  const double mb = static_cast<double>(pages) * static_cast<double>(page) / (1 << 20);
  return static_cast<std::size_t>(0.8 * mb / std::max(1, jobs));
}

void print_counts(const std::vector<ResultRow>& rows) {
  std::map<std::string, std::map<std::string, std::size_t>> counts;
  for (const auto& r : rows) ++counts[r.kernel][std::string(verdict_name(r.verdict))];
  for (const auto& [k, m] : counts) {
    std::cout << "  " << k << ":";
    for (const auto& [v, n] : m) std::cout << " " << v << "=" << n;
    std::cout << "\n";
  }
}

int run_command(const RunArgs& a, const std::string& command_line) {
  PlanOptions po;
  po.level = a.quick ? SweepLevel::quick : a.full ? SweepLevel::full : SweepLevel::normal;
  po.seeds = a.seeds;
  po.base_seed = a.base_seed;
  po.generators = a.generators;
  const std::vector<CaseSpec> plan = plan_sweep(po);

  Shard shard;
  std::string suffix;
  if (!a.shard.empty()) {
    shard = parse_shard(a.shard);
    suffix = "-shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count);
  }
  const std::vector<IndexedCase> cases = select_shard(plan, shard);

  RunOptions o;
  if (a.kernels.empty()) {
    for (const auto k : mk::kernel_names()) o.kernels.emplace_back(k);
  } else {
    for (const auto& k : a.kernels) {
      bool known = false;
      for (const auto n : mk::kernel_names()) known = known || n == k;
      if (!known) throw CLI::ValidationError("--kernels", "kernel '" + k + "' is not built into this library");
      o.kernels.push_back(k);
    }
  }
  o.jobs = std::max(1, a.jobs);
  o.timeout_seconds = a.timeout > 0 ? a.timeout : (a.quick ? 20 : a.full ? 300 : 60);
  o.memory_mb = a.memory_mb > 0 ? a.memory_mb : default_memory_mb(o.jobs);
  o.progress = ::isatty(2) != 0;

  fs::create_directories(a.out);
  const std::string level = a.quick ? "quick" : a.full ? "full" : "default";
  std::cerr << "mkbool-experiment: " << level << " sweep, base seed " << a.base_seed << " (case seeds derived from it; "
            << "column seed), " << cases.size() << " of " << plan.size() << " cases"
            << (suffix.empty() ? "" : " (shard " + a.shard + ")") << ", kernels " << join(o.kernels) << ", "
            << o.jobs << " jobs, time limit " << o.timeout_seconds << " s per run\n";
  const std::string csv = (fs::path(a.out) / ("results" + suffix + ".csv")).string();
  const std::string partial = csv + ".partial";
  SweepStats stats;
  const auto rows = run_sweep(cases, o, partial, &stats);
  {
    std::ofstream out(csv);
    out << csv_header() << "\n";
    for (const auto& r : rows) out << to_csv(r) << "\n";
    if (!out) throw std::runtime_error("cannot write " + csv);
  }
  fs::remove(partial);
  std::cerr << "mkbool-experiment: " << stats.rows << " runs in " << stats.seconds << " s, written to " << csv << "\n";

  std::size_t n_art = 0;
  if (!a.no_artefacts) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto arts = write_artefacts(rows, a.out, ArtefactOptions{3, std::min(60.0, o.timeout_seconds)});
    n_art = arts.size();
    if (!suffix.empty()) fs::rename(fs::path(a.out) / "artefacts.csv", fs::path(a.out) / ("artefacts" + suffix + ".csv"));
    std::cerr << "mkbool-experiment: " << n_art << " failure artefacts (pictures, regression cases) in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
    bool any_case = false;
    for (const auto& art : arts) {
      if (art.kind != Artefact::Kind::regression_case) continue;
      const bool core = art.path.find("inconsistency_") != std::string::npos;
      std::cerr << (core ? "  reference inconsistency: " : "  exact-kernel failure: ") << art.path << "\n";
      any_case = true;
    }
    if (any_case) {
      std::cerr << "  to keep them as tests: cp " << (fs::path(a.out) / "regression").string()
                << "/*.wkt tests/regression/cases/ (tests/regression replays every case there)\n";
    }
  }
  {
    std::ofstream sweep(fs::path(a.out) / ("sweep" + suffix + ".txt"));
    sweep << "command: `" << command_line << "`\n"
          << "level: " << level << "; base seed " << a.base_seed << "; seeds per configuration: "
          << (a.seeds > 0 ? std::to_string(a.seeds) : "level default") << "\n"
          << "kernels: " << join(o.kernels) << "\n"
          << "generators: " << (a.generators.empty() ? "all" : join(a.generators)) << "\n"
          << "shard: " << (a.shard.empty() ? "whole sweep" : a.shard) << "; " << cases.size() << " cases, "
          << stats.rows << " runs in " << stats.seconds << " s wall time with " << o.jobs << " jobs on "
          << std::thread::hardware_concurrency() << " hardware threads; time limit " << o.timeout_seconds
          << " s per run\n"
          << "finished: " << utc_now() << "\n";
  }
  std::cout << "verdicts:\n";
  print_counts(rows);
  if (!a.no_report && suffix.empty()) {
    const std::string readme = write_report(a.out, ReportOptions{!a.no_plots});
    std::cout << "report: " << readme << "\n";
  } else if (!suffix.empty()) {
    std::cout << "shard done; after all shards: mkbool-experiment merge -o DIR <shard dirs> (or report DIR)\n";
  }
  return 0;
}

int merge_command(const std::vector<std::string>& dirs, std::string out, bool plots) {
  if (out.empty()) out = dirs.front();
  fs::create_directories(out);
  std::vector<ResultRow> rows;
  std::vector<std::string> consumed;
  std::string artefacts_text, sweep_text;
  for (const auto& d : dirs) {
    for (const auto& e : fs::directory_iterator(d)) {
      const std::string name = e.path().filename().string();
      if (!e.is_regular_file()) continue;
      if (name.rfind("results", 0) == 0 && e.path().extension() == ".csv") {
        auto part = read_results(e.path().string());
        rows.insert(rows.end(), part.begin(), part.end());
        consumed.push_back(e.path().string());
      } else if (name.rfind("artefacts", 0) == 0 && e.path().extension() == ".csv") {
        std::ifstream in(e.path());
        std::string line;
        std::getline(in, line);  // header
        while (std::getline(in, line)) {
          // Paths are relative to the shard's directory; make them relative to out.
          const fs::path rel = fs::relative(fs::path(d), fs::path(out));
          const auto c1 = line.find(',');
          artefacts_text += line.substr(0, c1 + 1) + (rel == "." ? "" : rel.string() + "/") + line.substr(c1 + 1) + "\n";
        }
        consumed.push_back(e.path().string());
      } else if (name.rfind("sweep", 0) == 0 && e.path().extension() == ".txt") {
        std::ifstream in(e.path());
        sweep_text += std::string(std::istreambuf_iterator<char>(in), {});
        consumed.push_back(e.path().string());
      }
    }
  }
  std::stable_sort(rows.begin(), rows.end(), [](const ResultRow& x, const ResultRow& y) { return x.case_index < y.case_index; });
  // The shard files are moved aside so that DIR/results*.csv holds each run once.
  const fs::path aside = fs::path(out) / "shards";
  fs::create_directories(aside);
  for (const auto& f : consumed) {
    fs::path target = aside / fs::path(f).filename();
    for (int k = 1; fs::exists(target); ++k) target = aside / (fs::path(f).stem().string() + "-" + std::to_string(k) + fs::path(f).extension().string());
    fs::rename(f, target);
  }
  {
    std::ofstream csv(fs::path(out) / "results.csv");
    csv << csv_header() << "\n";
    for (const auto& r : rows) csv << to_csv(r) << "\n";
  }
  std::ofstream(fs::path(out) / "artefacts.csv") << "kind,path," << csv_header() << "\n" << artefacts_text;
  std::ofstream(fs::path(out) / "sweep.txt") << sweep_text;
  std::cout << "merged " << rows.size() << " runs into " << (fs::path(out) / "results.csv").string() << "\n";
  std::cout << "report: " << write_report(out, ReportOptions{plots}) << "\n";
  return 0;
}

int case_command(const CaseSpec& spec, const std::string& op_name, bool regular, const std::string& out) {
  const Case c = make_case(spec);
  const mk::Operation op = parse_operation(op_name);
  fs::create_directories(out);
  const std::string stem = spec.stem() + "_" + op_name + (regular ? "" : "_nonregular");
  std::ofstream(fs::path(out) / (stem + ".wkt")) << regression_case_text(
      c.a, c.b, op, regular, {"generator=" + spec.generator + " variant=" + spec.variant + " params=" +
                                  spec.params_text() + " seed=" + std::to_string(spec.seed)});
  const ExactResult ref = exact_reference(c.a, c.b, op, regular, false);
  std::cout << (fs::path(out) / (stem + ".wkt")).string() << ": " << c.size() << " input vertices, exact result "
            << ref.cycles.size() << " polygons\n";
  for (const auto k : mk::kernel_names()) {
    std::string verdict, title = std::string(k) + ": ";
    std::optional<mk::Output> output;
    try {
      output = mk::compute(c.a, c.b, mk::BooleanOptions{op, regular, std::string(k)}).output;
      const Assessment as = assess(*output, ref);
      verdict = std::string(verdict_name(as.verdict)) + (as.note.empty() ? "" : " (" + as.note + ")");
    } catch (const std::exception& e) {
      verdict = std::string("error (") + e.what() + ")";
    }
    const std::string svg = (fs::path(out) / (stem + "_" + std::string(k) + ".svg")).string();
    std::ofstream(svg) << failure_picture(c.a, c.b, ref.output, "exact " + op_name, output, title + verdict);
    std::cout << "  " << k << ": " << verdict << " -> " << svg << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mkbool-experiment: robustness sweeps of the mkbool kernels against the exact result"};
  app.require_subcommand(1);
  std::string command_line = "mkbool-experiment";
  for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];

  RunArgs ra;
  auto* run = app.add_subcommand("run", "run a sweep, write DIR/results*.csv, failure artefacts and DIR/README.md");
  auto* quick = run->add_flag("--quick", ra.quick, "small sweep (under 2 minutes on 2 cores)");
  run->add_flag("--full", ra.full, "long sweep (hours; see experiments/README.md)")->excludes(quick);
  run->add_option("--kernels", ra.kernels, "kernels to run (default: every kernel built)")->delimiter(',');
  run->add_option("--generators", ra.generators, "generators to run (default: all; see `list`)")->delimiter(',');
  run->add_option("--seeds", ra.seeds, "random instances per configuration (default: by level)")->check(CLI::PositiveNumber);
  run->add_option("--seed", ra.base_seed, "base seed; every case seed derives from it")->capture_default_str();
  run->add_option("--shard", ra.shard, "run only shard i of N (i/N, 0-based): every N-th case from i");
  run->add_option("--jobs,-j", ra.jobs, "worker processes")->capture_default_str()->check(CLI::PositiveNumber);
  run->add_option("--timeout", ra.timeout, "seconds per run before it counts as a timeout (default: 20 quick, 60, 300 full)");
  run->add_option("--memory-mb", ra.memory_mb, "address-space limit per worker (default: 80% of RAM / jobs)");
  run->add_flag("--no-artefacts", ra.no_artefacts, "skip failure pictures and regression cases");
  run->add_flag("--no-report", ra.no_report, "skip the report");
  run->add_flag("--no-plots", ra.no_plots, "report without running the plot script");
  run->add_option("-o,--out", ra.out, "output directory")->required();

  std::vector<std::string> merge_dirs;
  std::string merge_out;
  bool merge_no_plots = false;
  auto* merge = app.add_subcommand("merge", "join shard CSVs (DIR/results*.csv) into OUT/results.csv and report");
  merge->add_option("dirs", merge_dirs, "directories holding shard results")->required()->check(CLI::ExistingDirectory);
  merge->add_option("-o,--out", merge_out, "output directory (default: the first DIR)");
  merge->add_flag("--no-plots", merge_no_plots, "report without running the plot script");

  std::string report_dir;
  bool report_no_plots = false;
  auto* report = app.add_subcommand("report", "regenerate DIR/README.md (and plots) from DIR's CSV files");
  report->add_option("dir", report_dir, "sweep output directory")->required()->check(CLI::ExistingDirectory);
  report->add_flag("--no-plots", report_no_plots, "skip the plot script");

  auto* list = app.add_subcommand("list", "list generators (with variants) and kernels");

  CaseSpec spec;
  std::string case_params, case_op = "intersection", case_out = ".";
  bool case_nonregular = false;
  auto* one = app.add_subcommand("case", "regenerate one case: regression case file and a picture per kernel");
  one->add_option("--generator", spec.generator, "generator name")->required();
  one->add_option("--variant", spec.variant, "variant name (CSV column variant)")->required();
  one->add_option("--params", case_params, "parameters as in the CSV, e.g. k=-3 or i=4;j=8");
  one->add_option("--seed", spec.seed, "case seed (CSV column seed)")->required();
  one->add_option("--op", case_op, "intersection, union, difference or xor")->capture_default_str();
  one->add_flag("--nonregular", case_nonregular, "non-regular operation");
  one->add_option("-o,--out", case_out, "output directory")->capture_default_str();

  CLI11_PARSE(app, argc, argv);
  try {
    if (*run) return run_command(ra, command_line);
    if (*merge) return merge_command(merge_dirs, merge_out, !merge_no_plots);
    if (*report) {
      std::cout << "report: " << write_report(report_dir, ReportOptions{!report_no_plots}) << "\n";
      return 0;
    }
    if (*list) {
      for (const auto& g : generators()) {
        std::cout << g.name << ": " << g.stresses << "\n  variants:";
        for (const auto v : g.variants) std::cout << " " << v;
        std::cout << "\n";
      }
      std::cout << "kernels:";
      for (const auto k : mk::kernel_names()) std::cout << " " << k << (mk::is_exact_kernel(k) ? " (exact)" : "");
      std::cout << "\n";
      return 0;
    }
    if (*one) {
      spec.params = parse_params(case_params);
      return case_command(spec, case_op, !case_nonregular, case_out);
    }
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "mkbool-experiment: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
