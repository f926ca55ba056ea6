// The report's section on fill rules and union-all sets (issue 13): per generator of
// self-crossing input (generators_fill.cpp) or of sets (generators_set.cpp) and per kernel,
// regular and non-regular apart, how many runs gave the exact result, a valid but different
// one, an invalid one, or no result, and the runs' time.
// [BRIEF §1, extended by issue 13] [MK89 §3.3] (rounded constructions may fail: data)
// Preconditions: rows from run_sweep; rows of other generators are left out.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "api/mkbool.hpp"
#include "experiments/generators.hpp"
#include "experiments/report.hpp"
#include "experiments/statistics.hpp"

namespace mk::experiments {

namespace {

struct SetTally {
  std::size_t runs = 0, correct = 0, valid_different = 0, invalid = 0, failed = 0;
  std::vector<double> ms;  // op time of the runs that gave a result
};

std::string ms_cell(double v) {
  if (std::isnan(v)) return "";
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

}  // namespace

std::string fill_and_set_report(const std::vector<ResultRow>& rows) {
  // Generators in order of appearance, kernels in the library's order.
  std::vector<std::string> generators_seen;
  std::map<std::tuple<std::string, std::string, bool>, SetTally> tally;  // generator, kernel, regular
  std::set<std::string> kernels_seen;
  std::size_t reference_failures = 0;
  for (const auto& r : rows) {
    if (!is_fill_generator(r.generator) && !is_set_generator(r.generator)) continue;
    if (r.kernel == "reference") {
      ++reference_failures;
      continue;
    }
    if (std::find(generators_seen.begin(), generators_seen.end(), r.generator) == generators_seen.end()) {
      generators_seen.push_back(r.generator);
    }
    kernels_seen.insert(r.kernel);
    SetTally& t = tally[{r.generator, r.kernel, r.regular}];
    ++t.runs;
    switch (r.verdict) {
      case Verdict::exact_match: ++t.correct; break;
      case Verdict::valid_different: ++t.valid_different; break;
      case Verdict::invalid_output: ++t.invalid; break;
      default: ++t.failed;
    }
    if (r.op_ns) t.ms.push_back(static_cast<double>(*r.op_ns) * 1e-6);
  }
  if (tally.empty()) return {};
  std::vector<std::string> kernels;
  for (const auto k : kernel_names()) {
    if (kernels_seen.count(std::string(k))) kernels.emplace_back(k);
  }
  for (const auto& k : kernels_seen) {
    if (std::find(kernels.begin(), kernels.end(), k) == kernels.end()) kernels.push_back(k);
  }
  std::ostringstream md;
  md << "## Fill rules and union-all sets\n\n"
        "Self-crossing and multi-part input read by a fill rule (A op B), and sets of polygons through the "
        "N-ary operations (op `union_all`, `intersection_all`), each against the exact result of the rational "
        "kernel through the same library call. correct: `exact_match`; wrong: a valid result that is not the "
        "exact one (`valid_different`) or an invalid one (`invalid_output`); error: no result (`error`, "
        "`timeout`, `crash`, the message in the CSV). Time: median and total operation time of the runs with "
        "a result. Rounded-construction kernels may fail here: that is the data.\n\n";
  if (reference_failures > 0) {
    md << "**The exact reference failed on " << reference_failures
       << " (case, op, regular) of these generators: rows of kernel `reference` in the CSV.**\n\n";
  }
  md << "| generator | kernel | regular | runs | correct | wrong (valid) | wrong (invalid) | error | median ms | "
        "total s |\n|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& g : generators_seen) {
    for (const auto& k : kernels) {
      for (const bool regular : {true, false}) {
        const auto it = tally.find({g, k, regular});
        if (it == tally.end()) continue;
        const SetTally& t = it->second;
        double total_ms = 0;
        for (const double v : t.ms) total_ms += v;
        md << "| " << g << " | " << k << " | " << (regular ? "yes" : "no") << " | " << t.runs << " | " << t.correct
           << " | " << t.valid_different << " | " << t.invalid << " | " << t.failed << " | " << ms_cell(median(t.ms))
           << " | " << ms_cell(total_ms * 1e-3) << " |\n";
      }
    }
  }
  md << "\n";
  return md.str();
}

}  // namespace mk::experiments
