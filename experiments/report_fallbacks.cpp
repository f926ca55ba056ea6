// The report's section on the cost of exactness by fallback strategy: on the generators
// where filtered predicates fall back, the time of each exact strategy relative to `double`
// and the share of predicate calls each stage decided. [MK89 §3.3] (interval arithmetic
// with a multiprecision fallback) [Sh97 §4.2]
// Preconditions: rows from one sweep; stage shares need a build with MK_COUNTERS.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "arithmetic/predicates_counters.hpp"
#include "experiments/report.hpp"
#include "experiments/statistics.hpp"

namespace mk::experiments {

namespace {

// The strategies compared, in the order of the table, and what each falls back to.
struct Strategy {
  const char* kernel;
  const char* fallback;
};
constexpr Strategy strategies[] = {
    {"exact", "adaptive expansions and 128-bit fixed point, GMP last; implicit crossings (GMP when boxes overlap)"},
    {"interval", "double intervals, then MPFR intervals at 128 and 256 bits, GMP last; crossings rounded"},
    {"rational", "none: GMP rationals (`mpq_class`) for every predicate and crossing"},
    {"rational-mp", "none: GMP rationals through Boost.Multiprecision (`mpq_rational`)"},
    {"rational-cpp", "none: Boost's header-only rationals (`cpp_rational`)"},
};

std::string cell(double v, int digits) {
  if (std::isnan(v)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// "filter=120;interval=3" added into per-stage totals.
void add_stages(const std::string& text, std::map<std::string, double>& totals) {
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ';')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) continue;
    totals[item.substr(0, eq)] += std::stod(item.substr(eq + 1));
  }
}

// "filter 97.1%, mpfr_128 2.9%" in stage order.
std::string shares(const std::map<std::string, double>& totals) {
  double all = 0;
  for (const auto& [s, n] : totals) all += n;
  if (all == 0) return "";
  std::string out;
  for (std::size_t i = 0; i < PredicateCounters::stage_count; ++i) {
    const std::string name(stage_name(static_cast<PredicateStage>(i)));
    const auto it = totals.find(name);
    if (it == totals.end() || it->second == 0) continue;
    const double pct = 100.0 * it->second / all;
    out += (out.empty() ? "" : ", ") + name + " " + (pct < 0.01 ? std::string("<0.01") : cell(pct, pct < 1 ? 2 : 1)) + "%";
  }
  return out;
}

}  // namespace

void fallback_section(std::ostream& md, const std::vector<ResultRow>& rows) {
  std::set<std::string> present;
  for (const auto& r : rows) present.insert(r.kernel);
  std::vector<const Strategy*> shown;
  for (const auto& s : strategies) {
    if (present.count(s.kernel)) shown.push_back(&s);
  }
  if (shown.empty() || !present.count("double")) return;
  md << "## Cost of exactness by fallback strategy\n\n";
  md << "Each exact strategy against `double` on the same runs (median of per-run time ratios), on the generators "
        "where filtered predicates fall back (a call left the first filter in some run). The `rational` kernels "
        "give the same exact results by construction (tests assert it); `interval` decides exactly but rounds its "
        "crossing points, so its verdicts are those of the other rounding kernels.\n\n";
  md << "| kernel | fallback |\n|---|---|\n";
  for (const auto* s : shown) md << "| `" << s->kernel << "` | " << s->fallback << " |\n";
  md << "\n";

  // Generators with a fallback; without counters, every generator.
  bool counted = false;
  std::set<std::string> with_fallbacks, all_generators;
  for (const auto& r : rows) {
    all_generators.insert(r.generator);
    if (r.predicate_calls) counted = true;
    if (r.predicate_fallbacks && *r.predicate_fallbacks > 0) with_fallbacks.insert(r.generator);
  }
  const std::set<std::string>& generators = counted ? with_fallbacks : all_generators;
  if (!counted) {
    md << "This sweep was built without predicate counters (`-DMK_COUNTERS=ON`): every generator is listed and "
          "the stage shares are missing.\n\n";
  }
  if (generators.empty()) {
    md << "No predicate call left its filter in this sweep.\n\n";
    return;
  }

  std::map<std::tuple<std::uint64_t, std::string, bool>, double> double_ns;
  for (const auto& r : rows) {
    if (r.kernel == "double" && r.op_ns && *r.op_ns > 0) double_ns[{r.case_index, r.op, r.regular}] = static_cast<double>(*r.op_ns);
  }
  // generator -> kernel -> ratios; generator -> kernel -> stage totals; "all" rows too.
  std::map<std::string, std::map<std::string, std::vector<double>>> ratios;
  std::map<std::string, std::map<std::string, std::map<std::string, double>>> stages;
  for (const auto& r : rows) {
    if (!generators.count(r.generator) || !r.op_ns) continue;
    const auto it = double_ns.find({r.case_index, r.op, r.regular});
    if (it == double_ns.end()) continue;
    const double ratio = static_cast<double>(*r.op_ns) / it->second;
    ratios[r.generator][r.kernel].push_back(ratio);
    ratios[" all"][r.kernel].push_back(ratio);
    add_stages(r.predicate_stages, stages[r.generator][r.kernel]);
    add_stages(r.predicate_stages, stages[" all"][r.kernel]);
  }
  md << "Median time / `double`:\n\n| generator | runs |";
  for (const auto* s : shown) md << " `" << s->kernel << "` |";
  md << "\n|---|---:|";
  for (std::size_t i = 0; i < shown.size(); ++i) md << "---:|";
  md << "\n";
  for (const auto& [g, per_kernel] : ratios) {
    const auto d = per_kernel.find("double");
    md << "| " << (g == " all" ? std::string("**all of these**") : g) << " | "
       << (d == per_kernel.end() ? 0 : d->second.size()) << " |";
    for (const auto* s : shown) {
      const auto it = per_kernel.find(s->kernel);
      md << " " << (it == per_kernel.end() ? std::string() : cell(median(it->second), 2)) << " |";
    }
    md << "\n";
  }
  md << "\n";
  if (!counted) return;
  md << "Share of predicate calls each stage decided (`exact`: adaptive stages; `interval`: its own; the rational "
        "kernels have no stages):\n\n| generator | `exact` | `interval` |\n|---|---|---|\n";
  for (const auto& [g, per_kernel] : stages) {
    const auto e = per_kernel.find("exact");
    const auto i = per_kernel.find("interval");
    md << "| " << (g == " all" ? std::string("**all of these**") : g) << " | "
       << (e == per_kernel.end() ? std::string() : shares(e->second)) << " | "
       << (i == per_kernel.end() ? std::string() : shares(i->second)) << " |\n";
  }
  md << "\n";
}

}  // namespace mk::experiments
