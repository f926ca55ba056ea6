// The Markdown report of a sweep and the call of the plot script. [MK89 §3.3]
// Preconditions: see report.hpp.
#include "experiments/report.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "api/mkbool.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/report_library.hpp"
#include "experiments/report_rounding.hpp"
#include "experiments/statistics.hpp"

#ifndef MK_EXPERIMENTS_SOURCE_DIR
#define MK_EXPERIMENTS_SOURCE_DIR "experiments"
#endif

namespace mk::experiments {

namespace fs = std::filesystem;

namespace {

using Counts = std::map<Verdict, std::size_t>;

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string sci(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2g", v);
  return buf;
}

// Every rate with its count and 95% Wilson interval (statistics.hpp).
std::string rate_cell(std::size_t count, std::size_t total) { return rate_with_interval(count, total); }

std::size_t total(const Counts& c) {
  std::size_t n = 0;
  for (const auto& [v, k] : c) n += k;
  return n;
}

// Kernels in the library's order, then any others the CSV names ("reference" last).
std::vector<std::string> kernel_order(const std::vector<ResultRow>& rows) {
  std::vector<std::string> out;
  std::set<std::string> present;
  for (const auto& r : rows) present.insert(r.kernel);
  for (const auto k : kernel_names()) {
    if (present.count(std::string(k))) out.push_back(std::string(k));
  }
  for (const auto& k : present) {
    // Peers have verdicts of their own: they appear in the library comparison (report_library.cpp).
    if (std::find(out.begin(), out.end(), k) == out.end() && k != "reference" && !is_peer(k)) out.push_back(k);
  }
  if (present.count("reference")) out.push_back("reference");
  return out;
}

// Wrong beyond the rounding of constructed points.
bool is_wrong(const ResultRow& r) {
  switch (r.verdict) {
    case Verdict::exact_match:
    case Verdict::invalid_input: return false;
    case Verdict::valid_different: return r.area_error && !(*r.area_error <= 1e-12);
    default: return true;
  }
}

bool is_exact_name(const std::string& k) { return k != "reference" && is_exact_kernel(k); }

void verdict_table(std::ostream& md, const std::vector<std::string>& labels, const std::map<std::string, Counts>& counts,
                   const std::string& first_column) {
  md << "| " << first_column << " | runs |";
  for (const Verdict v : all_verdicts) md << " " << verdict_name(v) << " |";
  md << "\n|---|---:|";
  for (std::size_t i = 0; i < std::size(all_verdicts); ++i) md << "---:|";
  md << "\n";
  for (const auto& label : labels) {
    const auto it = counts.find(label);
    if (it == counts.end()) continue;
    const std::size_t n = total(it->second);
    md << "| " << label << " | " << n << " |";
    for (const Verdict v : all_verdicts) {
      const auto c = it->second.find(v);
      md << " " << rate_cell(c == it->second.end() ? 0 : c->second, n) << " |";
    }
    md << "\n";
  }
  md << "\n";
}

}  // namespace

std::string report_markdown(const std::vector<ResultRow>& rows, const std::vector<Artefact>& artefacts,
                            const std::vector<std::string>& sweep_lines, const std::vector<std::string>& plots) {
  std::ostringstream md;
  const std::vector<std::string> kernels = kernel_order(rows);
  std::vector<std::string> generator_names;
  std::map<std::string, Counts> by_kernel;
  std::map<std::string, std::map<std::string, Counts>> by_generator;  // generator -> kernel -> counts
  std::set<std::uint64_t> cases;
  for (const auto& r : rows) {
    if (std::find(generator_names.begin(), generator_names.end(), r.generator) == generator_names.end()) {
      generator_names.push_back(r.generator);
    }
    ++by_kernel[r.kernel][r.verdict];
    ++by_generator[r.generator][r.kernel][r.verdict];
    cases.insert(r.case_index);
  }

  md << "# mkbool robustness experiments\n\n";
  md << "Every run computes one Boolean operation of two generated polygons (or, for the set generators, the "
        "union or intersection of all polygons of a set) with one kernel and compares the result with the exact "
        "result of `RationalKernel`. Verdicts and the CSV columns are defined in "
        "`experiments/README.md` of the repository. " << cases.size() << " cases, " << rows.size() << " runs.\n\n";
  if (!sweep_lines.empty()) {
    md << "## Sweep\n\n";
    for (const auto& l : sweep_lines) md << "- " << l << "\n";
    md << "\n";
  }

  md << "## Verdicts per kernel\n\n";
  verdict_table(md, kernels, by_kernel, "kernel");
  std::size_t exact_failures = 0;
  for (const auto& r : rows) {
    if ((is_exact_name(r.kernel) || r.kernel == "reference") && r.verdict != Verdict::exact_match &&
        r.verdict != Verdict::refused) {
      ++exact_failures;
    }
  }
  std::string exact_list;
  for (const auto& k : kernels) {
    if (is_exact_name(k)) exact_list += (exact_list.empty() ? "`" : ", `") + k + "`";
  }
  if (exact_failures == 0) {
    md << "Exact kernels (" << exact_list << "): every run matched the exact result.\n\n";
  } else {
    md << "**Exact kernels (" << exact_list << ", or the reference itself): " << exact_failures
       << " runs did not match the exact result. Each is a bug; the cases are written as regression cases "
          "below.**\n\n";
  }

  md << fill_and_set_report(rows);
  md << library_report(rows);
  md << rounding_report(rows, artefacts);

  std::set<std::uint64_t> inconsistent_cases;
  std::size_t inconsistent_runs = 0;
  for (const auto& r : rows) {
    if (r.message.find("[reference inconsistency]") != std::string::npos) {
      ++inconsistent_runs;
      inconsistent_cases.insert(r.case_index);
    }
  }
  if (inconsistent_runs > 0) {
    md << "**The exact reference failed a consistency check in " << inconsistent_cases.size() << " cases ("
       << inconsistent_runs << " runs):** measuring the area error of a kernel's output K against the exact result R, "
          "`RationalKernel` gave area(K xor R) different from area(K) + area(R) - 2 area(K and R), with area(K) and "
          "area(R) computed without the core (nesting parity). That is a bug of the core, whatever the measured "
          "kernel did; those area errors are not to be trusted. Reproductions on double polygons:\n\n";
    std::size_t listed = 0;
    for (const auto& a : artefacts) {
      if (a.path.find("regression/inconsistency_") == std::string::npos) continue;
      md << "- [" << a.path << "](" << a.path << ") (from " << a.row.generator << " " << a.row.variant << ", seed "
         << a.row.seed << ", " << a.row.kernel << " " << a.row.op << ")\n";
      ++listed;
    }
    if (listed == 0) md << "- none reproduced on double polygons; see the rows with `[reference inconsistency]` in the CSV\n";
    md << "\n";
  }

  // Two views per generator: any difference from the exact result, and the differences
  // that are more than the rounding of constructed points.
  std::map<std::string, std::map<std::string, std::size_t>> wrong;  // generator -> kernel -> runs
  for (const auto& r : rows) {
    if (is_wrong(r)) ++wrong[r.generator][r.kernel];
  }
  const auto generator_table = [&](const std::string& title, const std::string& text, bool only_wrong) {
    md << "## " << title << "\n\n" << text << "\n\n| generator |";
    for (const auto& k : kernels) md << " " << k << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < kernels.size(); ++i) md << "---:|";
    md << "\n";
    for (const auto& g : generator_names) {
      md << "| " << g << " |";
      for (const auto& k : kernels) {
        const auto it = by_generator[g].find(k);
        if (it == by_generator[g].end()) {
          md << " |";
          continue;
        }
        const std::size_t n = total(it->second);
        const std::size_t ok = it->second.count(Verdict::exact_match) ? it->second.at(Verdict::exact_match) : 0;
        md << " " << rate_cell(only_wrong ? wrong[g][k] : n - ok, n) << " |";
      }
      md << "\n";
    }
    md << "\n";
  };
  generator_table("Wrong results per generator",
                  "Share of runs (count in brackets) whose result is wrong beyond rounding: `invalid_output`, "
                  "`error`, `timeout`, `crash`, or `valid_different` with an area error above 1e-12 (unmeasured area "
                  "errors, on outputs of thousands of polygons, are not counted).",
                  true);
  generator_table("Any difference per generator",
                  "Share of runs that are not `exact_match`: this includes crossing points rounded otherwise than to "
                  "nearest (area errors near 1e-16), which every kernel that constructs them in doubles shows.",
                  false);

  // Time relative to double, per (case, op, regular) with both timings.
  md << "## Time relative to `double`\n\n";
  std::map<std::tuple<std::uint64_t, std::string, bool>, double> double_ns;
  for (const auto& r : rows) {
    if (r.kernel == "double" && r.op_ns && *r.op_ns > 0) double_ns[{r.case_index, r.op, r.regular}] = static_cast<double>(*r.op_ns);
  }
  if (double_ns.empty()) {
    md << "No `double` runs with timings in this sweep.\n\n";
  } else {
    md << "Operation time only (no input conversion, no output assembly). The median is over runs; "
          "the total ratio sums all matched runs, so large inputs dominate it.\n\n";
    md << "| kernel | runs | median time / double | total time / double | total time (s) |\n|---|---:|---:|---:|---:|\n";
    for (const auto& k : kernels) {
      std::vector<double> ratios;
      double sum_k = 0, sum_d = 0;
      for (const auto& r : rows) {
        if (r.kernel != k || !r.op_ns) continue;
        const auto it = double_ns.find({r.case_index, r.op, r.regular});
        if (it == double_ns.end()) continue;
        ratios.push_back(static_cast<double>(*r.op_ns) / it->second);
        sum_k += static_cast<double>(*r.op_ns);
        sum_d += it->second;
      }
      if (ratios.empty()) continue;
      md << "| " << k << " | " << ratios.size() << " | " << fixed(median(ratios), 2) << " | " << fixed(sum_k / sum_d, 2)
         << " | " << fixed(sum_k * 1e-9, 3) << " |\n";
    }
    md << "\n";
  }
  // Median op time of the large workloads by size (intersection, regular).
  std::map<std::pair<std::string, std::uint64_t>, std::map<std::string, std::vector<double>>> sized;
  for (const auto& r : rows) {
    if ((r.generator == "blob" || r.generator == "star") && r.op == "intersection" && r.regular && r.op_ns) {
      sized[{r.generator, r.size}][r.kernel].push_back(static_cast<double>(*r.op_ns) * 1e-6);
    }
  }
  if (!sized.empty()) {
    md << "Median time (ms) of a regular intersection of the large workloads, by input vertices (A and B together):\n\n";
    md << "| workload | vertices |";
    for (const auto& k : kernels) md << " " << k << " |";
    md << "\n|---|---:|";
    for (std::size_t i = 0; i < kernels.size(); ++i) md << "---:|";
    md << "\n";
    for (auto& [key, per_kernel] : sized) {
      md << "| " << key.first << " | " << key.second << " |";
      for (const auto& k : kernels) {
        const auto it = per_kernel.find(k);
        md << " " << (it == per_kernel.end() ? std::string() : fixed(median(it->second), 3)) << " |";
      }
      md << "\n";
    }
    md << "\n";
  }

  fallback_section(md, rows);

  md << "## Area error of `valid_different` results\n\n"
        "Area of the symmetric difference between the kernel's output and the exact result, relative to the "
        "exact area (absolute when that is 0), computed exactly.\n\n";
  md << "Rounding a crossing point otherwise than to nearest moves the result by about 1e-16 (relative); "
        "errors above 1e-12 come from wrong decisions.\n\n";
  md << "| kernel | valid_different runs | area error <= 1e-12 | area error > 1e-12 | median area error | largest area error |"
        "\n|---|---:|---:|---:|---:|---:|\n";
  for (const auto& k : kernels) {
    std::vector<double> errs;
    for (const auto& r : rows) {
      if (r.kernel == k && r.verdict == Verdict::valid_different && r.area_error) errs.push_back(*r.area_error);
    }
    if (errs.empty()) continue;
    const auto small = static_cast<std::size_t>(std::count_if(errs.begin(), errs.end(), [](double e) { return e <= 1e-12; }));
    md << "| " << k << " | " << errs.size() << " | " << small << " | " << errs.size() - small << " | "
       << sci(median(errs)) << " | " << sci(*std::max_element(errs.begin(), errs.end())) << " |\n";
  }
  md << "\n";

  if (!plots.empty()) {
    md << "## Plots\n\n";
    for (const auto& p : plots) md << "![" << fs::path(p).stem().string() << "](" << p << ")\n\n";
  }

  md << "## Verdicts per generator\n\n";
  for (const auto& g : generator_names) {
    md << "### " << g << "\n\n";
    verdict_table(md, kernels, by_generator[g], "kernel");
  }

  md << "## Failure pictures and regression cases\n\n";
  // Pictures of snapped results are listed with the rounding tables above.
  std::vector<const Artefact*> failure_artefacts;
  for (const auto& a : artefacts) {
    if (a.kind != Artefact::Kind::snapping) failure_artefacts.push_back(&a);
  }
  if (failure_artefacts.empty()) {
    md << "None: no failures, or the artefact step was skipped.\n\n";
  } else {
    md << "Every failure of an exact kernel (as a regression case file and a picture), and for each other kernel "
          "and generator the three smallest failing cases, worst verdicts first (crash, timeout, invalid output, "
          "error, then area errors above 1e-12). Pictures: A, B and the exact result on the left, the kernel's "
          "result on the right, and a zoom on the first difference when it is too small to see.\n\n";
  }
  std::map<std::string, std::vector<const Artefact*>> by_kernel_art;
  for (const Artefact* a : failure_artefacts) by_kernel_art[a->row.kernel].push_back(a);
  for (const auto& k : kernels) {
    const auto it = by_kernel_art.find(k);
    if (it == by_kernel_art.end()) continue;
    md << "### " << k << "\n\n| generator | variant | params | seed | op | vertices | verdict | area error | file |\n"
          "|---|---|---|---:|---|---:|---|---:|---|\n";
    for (const Artefact* a : it->second) {
      const ResultRow& r = a->row;
      md << "| " << r.generator << " | " << r.variant << " | " << r.params << " | " << r.seed << " | " << r.op
         << (r.regular ? "" : " (non-regular)") << " | " << r.size << " | " << verdict_name(r.verdict) << " | "
         << (r.area_error ? sci(*r.area_error) : std::string()) << " | ["
         << (a->kind == Artefact::Kind::picture ? "picture" : "regression case") << "](" << a->path << ") |\n";
    }
    md << "\n";
  }
  md << "## Reproducing\n\nEvery case is a generator, a variant, parameters and a seed (CSV columns): "
        "`mkbool-experiment case --generator G --variant V --params P --seed S -o DIR` writes it as a regression "
        "case file and pictures it for every kernel. `mkbool-experiment report DIR` rebuilds this page from the "
        "CSV files.\n";
  return md.str();
}

std::string plot_script_path() {
  if (const char* env = std::getenv("MK_EXPERIMENT_PLOTS")) return env;
  char buf[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n > 0) {
    const fs::path next_to = fs::path(std::string(buf, static_cast<std::size_t>(n))).parent_path() / "mkbool-experiment-plots.py";
    if (fs::exists(next_to)) return next_to.string();
  }
  return std::string(MK_EXPERIMENTS_SOURCE_DIR) + "/plots.py";
}

std::string write_report(const std::string& dir, const ReportOptions& options) {
  const std::vector<ResultRow> rows = read_results_dir(dir);
  const std::vector<Artefact> artefacts = read_artefacts(dir);
  std::vector<std::string> sweep_lines;
  std::vector<fs::path> sweep_files;  // sweep.txt, or one per shard
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("sweep", 0) == 0 && e.path().extension() == ".txt") sweep_files.push_back(e.path());
  }
  std::sort(sweep_files.begin(), sweep_files.end());
  for (const auto& f : sweep_files) {
    std::ifstream in(f);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty()) sweep_lines.push_back(line);
    }
  }
  std::vector<std::string> plots;
  if (options.plots) {
    const std::string script = plot_script_path();
    const std::string cmd = options.python + " '" + script + "' '" + dir + "'";
    if (std::system(cmd.c_str()) != 0) {
      sweep_lines.push_back("plots: `" + cmd + "` failed (is python3-matplotlib installed?)");
    }
  }
  if (fs::exists(fs::path(dir) / "plots")) {
    for (const auto& e : fs::directory_iterator(fs::path(dir) / "plots")) {
      if (e.path().extension() == ".png") plots.push_back("plots/" + e.path().filename().string());
    }
    std::sort(plots.begin(), plots.end());
  }
  const fs::path readme = fs::path(dir) / "README.md";
  std::ofstream out(readme);
  out << report_markdown(rows, artefacts, sweep_lines, plots);
  if (!out) throw std::runtime_error("cannot write " + readme.string());
  return readme.string();
}

}  // namespace mk::experiments
