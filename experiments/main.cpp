// mkbool-experiment: run robustness sweeps (generators x kernels x operations x regular x
// seeds), merge shards, write the report, and reproduce single cases. [MK89 §3.3]
// Preconditions: none; every bad argument exits with status 2 and one line naming it.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <thread>

#include <gmp.h>

#include "api/mkbool.hpp"
#include "arithmetic/snap_grid.hpp"
#include "build_commit.hpp"
#include "experiments/arguments.hpp"
#include "experiments/artefacts.hpp"
#include "experiments/external_cases.hpp"
#include "experiments/generators.hpp"
#include "experiments/operations.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/report.hpp"
#include "experiments/runner.hpp"
#include "experiments/snapping_pictures.hpp"

namespace fs = std::filesystem;
using namespace mk::experiments;
using namespace mk::experiments::arguments;

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
  bool no_artefacts = false, no_report = false, no_plots = false, no_peers = false;
  std::size_t peer_every = 0;
  std::string cases;
  std::string out;
  std::string rounding = "certified";
  std::string grid;
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

std::string first_line_of(const std::string& command) {
  std::string out;
  if (FILE* f = ::popen(command.c_str(), "r")) {
    char buf[512];
    if (std::fgets(buf, sizeof buf, f) != nullptr) out = buf;
    ::pclose(f);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

// What the sweep ran on: the commit, the libraries' versions, the compiler and the CPU.
std::vector<std::string> environment_lines() {
  std::vector<std::string> out;
  // The commit the binary was built from (build_commit.cmake), not the checkout's HEAD now:
  // the two differ when the tree moved on since the build.
  std::string commit = MK_BUILD_COMMIT;
  const std::string src = MK_EXPERIMENTS_SOURCE_DIR;
  const std::string now = first_line_of("git -C '" + src + "' rev-parse --short=12 HEAD 2>/dev/null");
  if (!now.empty() && commit.compare(0, now.size(), now) != 0) commit += "; the source tree is now at " + now;
  out.push_back("commit: " + commit);
  std::string libs = std::string("GMP ") + gmp_version;
  for (const auto& v : peer_versions()) libs += ", " + v;
  out.push_back("libraries: " + libs);
  out.push_back("compiler: " + std::string(
#if defined(__clang__)
      "clang "
#elif defined(__GNUC__)
      "GCC "
#endif
      __VERSION__));
  std::ifstream cpu("/proc/cpuinfo");
  std::string line, model = "unknown";
  while (std::getline(cpu, line)) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  out.push_back("cpu: " + model + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads");
  return out;
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
  if (!a.cases.empty()) {
    set_user_cases(a.cases);
    if (po.generators.empty()) po.generators = {"cases"};
  }
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
    // The number-type variants of `rational` (same results, several times its cost) only in
    // the full sweep, so that the default sweep keeps its few minutes.
    for (const auto k : mk::kernel_names()) {
      if (a.full || !mk::is_number_type_variant(k)) o.kernels.emplace_back(k);
    }
    if (!a.no_peers) {
      for (const auto p : peer_names()) o.kernels.emplace_back(p);
    }
  } else {
    o.kernels = a.kernels;  // checked while parsing (kernels and peers)
  }
  // Peers run on every external case; on generated cases the default sweep samples them
  // (every 4th case, inputs up to 2000 vertices), --full runs them all.
  o.peer_every = a.peer_every > 0 ? a.peer_every : a.full ? 1 : 4;
  o.peer_max_size = a.full ? 0 : 2000;
  o.jobs = std::max(1, a.jobs);
  o.timeout_seconds = a.timeout > 0 ? a.timeout : (a.quick ? 20 : a.full ? 300 : 60);
  o.memory_mb = a.memory_mb > 0 ? a.memory_mb : default_memory_mb(o.jobs);
  o.progress = ::isatty(2) != 0;
  o.rounding = a.rounding == "nearest" ? mk::RoundingMode::nearest : mk::RoundingMode::certified;
  o.grid = a.grid;

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
    const auto snapping = static_cast<std::size_t>(std::count_if(
        arts.begin(), arts.end(), [](const Artefact& art) { return art.kind == Artefact::Kind::snapping; }));
    n_art = arts.size() - snapping;
    if (!suffix.empty()) fs::rename(fs::path(a.out) / "artefacts.csv", fs::path(a.out) / ("artefacts" + suffix + ".csv"));
    std::cerr << "mkbool-experiment: " << n_art << " failure artefacts (pictures, regression cases) and " << snapping
              << " pictures of snapped results in "
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
          << "peers: on every external case; on generated cases with index divisible by " << o.peer_every
          << (o.peer_max_size > 0 ? " and at most " + std::to_string(o.peer_max_size) + " input vertices" : std::string())
          << ", regular operations\n"
          << "rounding of the written output: " << a.rounding
          << (a.grid.empty() ? std::string(" (grid of doubles at the result's scale when snapping)") : "; grid " + a.grid) << "\n"
          << "finished: " << utc_now() << "\n";
    for (const auto& l : environment_lines()) sweep << l << "\n";
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

int case_command(const CaseSpec& spec, const std::string& op_name, bool regular, const std::string& out, bool pictures) {
  const Case c = make_case(spec);
  const mk::Operation op = parse_run_operation(op_name);
  if (!runs_operation(spec, op)) {
    throw std::invalid_argument("generator " + spec.generator + " makes sets: --op union or intersection (union_all, intersection_all)");
  }
  const std::string run_name = run_operation_name(spec, op);
  fs::create_directories(out);
  // External cases are named by their id (a production case keeps its name as a test).
  const std::string stem = (is_external_generator(spec.generator) ? spec.generator + "_" + spec.variant : spec.stem()) +
                           "_" + run_name + (regular ? "" : "_nonregular");
  std::ofstream(fs::path(out) / (stem + ".wkt")) << regression_case_text(
      c, op, regular, {"generator=" + spec.generator + " variant=" + spec.variant + " params=" +
                           spec.params_text() + " seed=" + std::to_string(spec.seed)});
  const ExactResult ref = case_reference(c, op, regular, false);
  std::cout << (fs::path(out) / (stem + ".wkt")).string() << ": " << c.size() << " input vertices, exact result "
            << ref.cycles.size() << " polygons\n";
  if (!pictures) return 0;
  for (const auto k : mk::kernel_names()) {
    std::string verdict, title = std::string(k) + ": ";
    std::optional<mk::Output> output;
    try {
      mk::BooleanOptions options{op, regular, std::string(k)};
      options.exact_coordinates = true;  // assess() compares exact results exactly
      output = run_operation(c, options).output;  // with the case's fill rule
      const Assessment as = assess(*output, ref);
      verdict = std::string(verdict_name(as.verdict)) + (as.note.empty() ? "" : " (" + as.note + ")");
    } catch (const std::exception& e) {
      verdict = std::string("error (") + e.what() + ")";
    }
    const std::string svg = (fs::path(out) / (stem + "_" + std::string(k) + ".svg")).string();
    std::ofstream(svg) << failure_picture(c.a, c.b, ref.output, "exact " + run_name, output, title + verdict);
    std::cout << "  " << k << ": " << verdict << " -> " << svg << "\n";
    if (k == "exact" && output && output->rounding.snapped) {
      // Certified rounding snapped the result: the nearest doubles beside the snapped output.
      const std::string snapped = (fs::path(out) / (stem + "_snapping.svg")).string();
      std::ofstream(snapped) << snapping_picture(c, op, regular, std::string(k));
      std::cout << "  " << k << ": snapped to grid " << output->rounding.grid << " -> " << snapped << "\n";
    }
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
  const auto backend_check = accepted_by(
      [](const std::string& k) { check_backend(k); },
      "back end");
  const auto generator_check = accepted_by([](const std::string& g) { find_generator(g); }, "generator");
  run->add_option("--kernels,--backends", ra.kernels, "back ends to run: kernels and peers (default: every one built; rational-mp and rational-cpp only with --full)")
      ->delimiter(',')
      ->check(backend_check);
  run->add_flag("--no-peers", ra.no_peers, "kernels only (no GEOS, Boost.Geometry, Clipper, CGAL)");
  run->add_option("--peer-every", ra.peer_every, "run peers on every N-th generated case (default: 4; --full: 1)")
      ->check(whole_number(1, 1'000'000, "a whole number from 1 to 1000000"));
  run->add_option("--cases", ra.cases, "sweep your own pairs: JSON Lines of the batch format (id, op, a_wkt, b_wkt)")
      ->check(CLI::ExistingFile);
  run->add_option("--generators", ra.generators, "generators to run (default: all; see `list`)")
      ->delimiter(',')
      ->check(generator_check);
  run->add_option("--seeds", ra.seeds, "random instances per configuration (default: by level)")
      ->check(whole_number(1, 1'000'000, "a whole number of seeds from 1 to 1000000"));
  run->add_option("--seed", ra.base_seed, "base seed; every case seed derives from it")
      ->capture_default_str()
      ->check(whole_number(0, UINT64_MAX, "a whole number from 0 to 2^64-1"));
  run->add_option("--shard", ra.shard, "run only shard i of N (i/N, 0-based): every N-th case from i")
      ->check(accepted_by([](const std::string& t) { parse_shard(t); }, "shard"));
  run->add_option("--jobs,-j", ra.jobs, "worker processes")
      ->capture_default_str()
      ->check(whole_number(1, 1024, "a whole number of worker processes from 1 to 1024"));
  run->add_option("--timeout", ra.timeout, "seconds per run before it counts as a timeout (default: 20 quick, 60, 300 full)")
      ->check(positive_seconds());
  run->add_option("--memory-mb", ra.memory_mb, "address-space limit per worker (default: 80% of RAM / jobs)")
      ->check(whole_number(1, UINT64_MAX >> 20, "a whole number of megabytes, at least 1"));
  run->add_option("--rounding", ra.rounding,
                  "rounding of each kernel's written output, recorded in the rounding columns: certified (default: the "
                  "nearest doubles when valid, else snap rounding) or nearest")
      ->check(CLI::IsMember({"certified", "nearest"}));
  run->add_option("--grid", ra.grid, "snap every result onto multiples of G (a positive decimal or fraction p/q, exact)")
      ->check(arguments::accepted_by([](const std::string& g) { (void)mk::SnapGrid::parse(g); }, "grid"));
  run->add_flag("--no-artefacts", ra.no_artefacts, "skip failure pictures, regression cases and pictures of snapped results");
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
  std::string case_params, case_op = "intersection", case_out = ".", case_file;
  bool case_nonregular = false, case_no_pictures = false;
  auto* one = app.add_subcommand("case", "regenerate one case: regression case file and a picture per kernel");
  one->add_option("--generator", spec.generator, "generator name")->required()->check(generator_check);
  one->add_option("--variant", spec.variant, "variant name (CSV column variant)")->required();
  one->add_option("--params", case_params, "parameters as in the CSV, e.g. k=-3 or i=4;j=8");
  one->add_option("--seed", spec.seed, "case seed (CSV column seed; any value for reported and cases)")
      ->check(whole_number(0, UINT64_MAX, "a whole number from 0 to 2^64-1"));
  one->add_option("--op", case_op, "intersection, union, difference or xor (or symdifference); set generators: union or intersection (or union_all, intersection_all)")
      ->capture_default_str()
      ->check(accepted_by([](const std::string& op) { parse_run_operation(operation_argument(op)); }, "operation"));
  one->add_flag("--nonregular", case_nonregular, "non-regular operation");
  one->add_option("-o,--out", case_out, "output directory")->capture_default_str();
  one->add_option("--cases", case_file, "JSON Lines file of generator `cases` (the case is --variant ID)")->check(CLI::ExistingFile);
  one->add_flag("--no-pictures", case_no_pictures, "write the regression case file only");

  // CLI11's own exit codes (104-106) and multi-line messages become exit 2 and one line.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string first = argv[1];
    bool known = false;
    for (const auto* sub : app.get_subcommands({})) known = known || sub->get_name() == first;
    if (!known) return usage_error("unknown command '" + first + "' (run, merge, report, list or case)");
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    return usage_error(e.what());
  }
  // Checks that need more than one argument, or a look at the file system.
  if (*one) {
    const auto& variants = find_generator(spec.generator).variants;
    // External generators' variants are case ids, checked when the case is looked up.
    if (!is_external_generator(spec.generator) &&
        std::find(variants.begin(), variants.end(), spec.variant) == variants.end()) {
      std::string known;
      for (const auto v : variants) known += (known.empty() ? "" : ", ") + std::string(v);
      return usage_error("--variant: generator " + spec.generator + " has no variant '" + spec.variant +
                         "' (it has: " + known + ")");
    }
    try {
      spec.params = parse_params(case_params);
    } catch (const std::invalid_argument& e) {
      return usage_error(std::string("--params: ") + e.what());
    }
    case_op = operation_argument(case_op);
  }
  if (*report && !has_results(report_dir)) {
    return usage_error(report_dir + " holds no results*.csv; run `mkbool-experiment run -o " + report_dir + "` first");
  }
  if (*merge && std::none_of(merge_dirs.begin(), merge_dirs.end(), has_results)) {
    return usage_error("none of the directories holds results*.csv files to merge");
  }
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
      std::cout << "\npeers:";
      for (const auto p : peer_names()) std::cout << " " << p;
      std::cout << "\nreported corpus: " << reported_corpus().size() << " cases in " << reported_dir() << "\n";
      return 0;
    }
    if (*one) {
      if (!case_file.empty()) set_user_cases(case_file);
      return case_command(spec, case_op, !case_nonregular, case_out, !case_no_pictures);
    }
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "mkbool-experiment: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
