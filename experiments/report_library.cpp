// The library comparison sections of the report. [BRIEF §5] [MK89 §3.3]
// Preconditions: see report_library.hpp. The corpus tables are in report_corpus.cpp.
#include "experiments/report_library.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "api/mkbool.hpp"
#include "experiments/generators.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/statistics.hpp"

namespace mk::experiments {

std::string_view outcome_name(Outcome o) {
  switch (o) {
    case Outcome::exact: return "exact";
    case Outcome::rounding_only: return "rounding only";
    case Outcome::wrong: return "wrong";
    case Outcome::invalid_output: return "invalid output";
    case Outcome::exception: return "exception";
    case Outcome::crash: return "crash";
    case Outcome::timeout: return "timeout";
    case Outcome::refused: return "refused";
    case Outcome::unjudged: return "unjudged";
    case Outcome::unsupported: return "unsupported";
  }
  return "?";
}

Outcome outcome(const ResultRow& r) {
  switch (r.verdict) {
    case Verdict::exact_match:
    case Verdict::exact_area: return Outcome::exact;
    case Verdict::rounding_only: return Outcome::rounding_only;
    case Verdict::valid_different:
      if (!r.symdiff_area) return Outcome::unjudged;
      if (*r.symdiff_area == 0) return Outcome::exact;  // the same region, other vertices
      return r.rounding_bound && *r.symdiff_area <= *r.rounding_bound ? Outcome::rounding_only : Outcome::wrong;
    case Verdict::wrong: return Outcome::wrong;
    case Verdict::invalid_output: return Outcome::invalid_output;
    case Verdict::error: return r.message.rfind("InvalidInput", 0) == 0 ? Outcome::refused : Outcome::exception;
    case Verdict::exception: return Outcome::exception;
    case Verdict::crash: return Outcome::crash;
    case Verdict::timeout: return Outcome::timeout;
    case Verdict::refused:
    case Verdict::invalid_input: return Outcome::refused;
    case Verdict::unjudged: return Outcome::unjudged;
    case Verdict::unsupported: return Outcome::unsupported;
  }
  return Outcome::unjudged;
}

std::string markdown_cell(std::string s) {
  for (char& c : s) {
    if (c == '|' || c == '\n') c = ' ';
  }
  return s;
}

bool is_failure(Outcome o) {
  return o == Outcome::wrong || o == Outcome::invalid_output || o == Outcome::exception || o == Outcome::crash ||
         o == Outcome::timeout;
}

namespace {

using RunKey = std::tuple<std::uint64_t, std::string, bool>;  // case, op, regular

bool is_judged(Outcome o) { return o != Outcome::refused && o != Outcome::unjudged && o != Outcome::unsupported; }

// Kernels in the library's order, then peers in theirs.
std::vector<std::string> backend_order(const std::vector<ResultRow>& rows) {
  std::set<std::string> present;
  for (const auto& r : rows) present.insert(r.kernel);
  std::vector<std::string> out;
  for (const auto k : kernel_names()) {
    if (present.count(std::string(k))) out.emplace_back(k);
  }
  for (const auto p : peer_names()) {
    if (present.count(std::string(p))) out.emplace_back(p);
  }
  for (const auto& k : present) {
    if (k != "reference" && std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  }
  return out;
}

struct LibraryTally {
  std::map<Outcome, std::size_t> outcomes;
  std::size_t runs = 0, failed_runs = 0;
  std::set<std::uint64_t> cases, failed_cases;
  void add(const ResultRow& r) {
    const Outcome o = outcome(r);
    ++outcomes[o];
    ++runs;
    cases.insert(r.case_index);
    if (is_failure(o)) {
      ++failed_runs;
      failed_cases.insert(r.case_index);
    }
  }
};

void header(std::ostringstream& md, const std::string& first, const std::vector<std::string>& columns) {
  md << "| " << first << " |";
  for (const auto& c : columns) md << " " << c << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) md << "---:|";
  md << "\n";
}


void comparison_table(std::ostringstream& md, const std::vector<std::string>& backends,
                      const std::map<std::string, LibraryTally>& tallies) {
  std::vector<std::string> cols{"runs"};
  for (const Outcome o : all_outcomes) cols.emplace_back(outcome_name(o));
  cols.insert(cols.end(), {"failed runs", "cases", "failed cases"});
  header(md, "back end", cols);
  for (const auto& b : backends) {
    const auto it = tallies.find(b);
    if (it == tallies.end()) continue;
    const LibraryTally& t = it->second;
    md << "| " << b << (is_peer(b) ? "" : " (mkbool)") << " | " << t.runs << " |";
    for (const Outcome o : all_outcomes) {
      const auto c = t.outcomes.find(o);
      md << " " << (c == t.outcomes.end() ? std::string("0") : rate_with_interval(c->second, t.runs)) << " |";
    }
    md << " " << rate_with_interval(t.failed_runs, t.runs) << " | " << t.cases.size() << " | "
       << rate_with_interval(t.failed_cases.size(), t.cases.size()) << " |\n";
  }
  md << "\n";
}

}  // namespace

std::string library_report(const std::vector<ResultRow>& rows) {
  const std::vector<std::string> backends = backend_order(rows);
  const bool any_peer = std::any_of(rows.begin(), rows.end(), [](const ResultRow& r) { return is_peer(r.kernel); });
  const bool any_external = std::any_of(rows.begin(), rows.end(), [](const ResultRow& r) { return is_external_generator(r.generator); });
  std::ostringstream md;
  if (!any_peer && !any_external) return {};

  // The runs every back end ran: the same (case, op, regular) for all.
  std::map<RunKey, std::map<std::string, const ResultRow*>> by_run;
  for (const auto& r : rows) {
    if (r.kernel != "reference") by_run[{r.case_index, r.op, r.regular}][r.kernel] = &r;
  }
  std::map<std::string, LibraryTally> common;
  std::size_t common_runs = 0;
  for (const auto& [key, m] : by_run) {
    if (m.size() != backends.size()) continue;
    ++common_runs;
    for (const auto& [b, r] : m) common[b].add(*r);
  }

  md << "## Libraries and kernels on the same runs\n\n"
        "One scale for mkbool's kernels and the peer libraries (GEOS OverlayNG through its C API, Boost.Geometry "
        "in doubles, Clipper 6.4 on integers scaled by a power of two, CGAL Boolean_set_operations_2 with Epeck): "
        "*exact* (kernels: the exact result vertex for vertex; peers: the exact area and an empty symmetric "
        "difference with the exact result, computed exactly), *rounding only* (symmetric difference within the "
        "rounding bound 2·δ·(P_exact + P_result), δ = 2^-50 × the largest input coordinate, or Clipper's grid "
        "spacing if larger, P the perimeters: what moving every vertex by δ can cost), *wrong* (beyond it), "
        "*invalid output* (for peers: GEOS's isValid or our exact OGC check rejects it; both are in the CSV), "
        "*exception* (the library threw, e.g. GEOS TopologyException; for kernels KernelFailure), *crash*, "
        "*timeout*, *refused* (mkbool refused an input outside its domain), *unjudged* (no exact result to "
        "compare with; the output is valid), *unsupported* (an OGC library cannot take a hole-type polygon). "
        "Peers run the regular operations only; on generated cases the default sweep samples them (`sweep.txt` "
        "says how), `--full` runs them on every case. Every rate has its count and its 95% Wilson interval. "
        "A case fails when any of its runs fails (runs of one case are correlated).\n\n";
  md << "### Runs that every back end ran (" << common_runs << " runs)\n\n";
  comparison_table(md, backends, common);
  std::map<std::string, LibraryTally> all;
  for (const auto& r : rows) {
    if (r.kernel != "reference") all[r.kernel].add(r);
  }
  md << "### Every run of each back end\n\n";
  comparison_table(md, backends, all);

  // The independent oracle for the exact kernels.
  std::size_t compared = 0, agree = 0, cgal_wrong = 0, mkbool_wrong = 0, undecided = 0;
  std::vector<const ResultRow*> disagreements;
  for (const auto& r : rows) {
    if (!r.oracle_agrees) continue;
    ++compared;
    if (*r.oracle_agrees) {
      ++agree;
      continue;
    }
    disagreements.push_back(&r);
    if (r.message.find("cgal_epeck wrong") != std::string::npos) ++cgal_wrong;
    else if (r.message.find("MKBOOL WRONG") != std::string::npos) ++mkbool_wrong;
    else ++undecided;
  }
  if (compared > 0) {
    std::string exact_kernels;
    for (const auto k : kernel_names()) {
      if (is_exact_kernel(k)) exact_kernels += (exact_kernels.empty() ? "`" : ", `") + std::string(k) + "`";
    }
    md << "## Exact kernels against an independent exact implementation\n\n"
       << "**Exact kernels (" << exact_kernels << ") agree with CGAL Epeck (Boolean_set_operations_2, exact "
       << "constructions) on " << agree << " of " << compared << " runs** (" << rate_with_interval(agree, compared)
       << "). Compared exactly: a kernel agrees when its result equals the exact reference vertex for vertex and "
          "the reference has CGAL's exact area (as a rational) and an empty exact symmetric difference with CGAL's "
          "result (column `oracle_agrees`). Runs where CGAL gave no result (crash, exception) are not counted.\n\n";
    if (!disagreements.empty()) {
      md << "Of the " << disagreements.size() << " disagreements, an independent point check (a point inside the "
         << "symmetric difference of the two results, located in A, B and both results by exact crossing parity "
            "written for the harness, not the core) finds CGAL wrong in "
         << cgal_wrong << ", mkbool wrong in " << mkbool_wrong << ", and cannot decide " << undecided
         << ". CGAL 5.5 is known to be wrong on holes touching their shell at a vertex that lies on an edge of the "
            "other polygon (shared/design/public-failure-reports.md).\n\n";
      md << "| generator | variant | seed | op | kernel | finding |\n|---|---|---:|---|---|---|\n";
      for (std::size_t i = 0; i < disagreements.size() && i < 20; ++i) {
        const ResultRow& r = *disagreements[i];
        const auto at = r.message.find("oracle: ");
        md << "| " << r.generator << " | " << r.variant << " | " << r.seed << " | " << r.op
           << (r.regular ? "" : " (non-regular)") << " | " << r.kernel << " | "
           << markdown_cell(at == std::string::npos ? r.message : r.message.substr(at)) << " |\n";
      }
      if (disagreements.size() > 20) md << "\n(" << disagreements.size() - 20 << " more in the CSV.)\n";
      md << "\n";
    }
  }

  // Failure maps: generator x back end.
  std::vector<std::string> generators;
  std::map<std::string, std::map<std::string, LibraryTally>> by_generator;
  for (const auto& r : rows) {
    if (r.kernel == "reference") continue;
    if (std::find(generators.begin(), generators.end(), r.generator) == generators.end()) generators.push_back(r.generator);
    by_generator[r.generator][r.kernel].add(r);
  }
  for (const bool per_case : {false, true}) {
    md << "## Failure map per generator" << (per_case ? ", per case" : ", per run") << "\n\n"
       << (per_case ? "Share of cases with at least one failed run (wrong, invalid output, exception, crash, timeout)."
                    : "Share of runs that failed (wrong, invalid output, exception, crash, timeout).")
       << " Empty: the back end did not run there.\n\n";
    header(md, "generator", backends);
    for (const auto& g : generators) {
      md << "| " << g << " |";
      for (const auto& b : backends) {
        const auto it = by_generator[g].find(b);
        if (it == by_generator[g].end()) {
          md << " |";
          continue;
        }
        const LibraryTally& t = it->second;
        md << " " << (per_case ? rate_with_interval(t.failed_cases.size(), t.cases.size()) : rate_with_interval(t.failed_runs, t.runs))
           << " |";
      }
      md << "\n";
    }
    md << "\n";
  }

  // By operation and by regularity.
  md << "## Failed runs by operation and regularity\n\n";
  std::vector<std::string> cols;
  for (const char* op : {"intersection", "union", "difference", "xor"}) cols.emplace_back(op);
  cols.insert(cols.end(), {"regular", "non-regular"});
  header(md, "back end", cols);
  for (const auto& b : backends) {
    md << "| " << b << " |";
    for (const auto& c : cols) {
      std::size_t n = 0, f = 0;
      for (const auto& r : rows) {
        if (r.kernel != b) continue;
        const bool match = c == "regular" ? r.regular : c == "non-regular" ? !r.regular : r.op == c;
        if (!match) continue;
        ++n;
        f += is_failure(outcome(r)) ? 1 : 0;
      }
      md << " " << (n == 0 ? std::string() : rate_with_interval(f, n)) << " |";
    }
    md << "\n";
  }
  md << "\n";

  // Pairwise agreement on runs both judged.
  md << "## Agreement between back ends\n\nOn the runs both back ends ran and both were judged, the share where "
        "they agree: both correct (exact or rounding only) or both failed, with its 95% Wilson interval and the number "
        "of runs. The last column counts runs where this back end failed and every other judged back end was "
        "correct.\n\n";
  std::vector<std::string> agree_cols = backends;
  agree_cols.push_back("fails alone");
  header(md, "", agree_cols);
  for (const auto& x : backends) {
    md << "| " << x << " |";
    for (const auto& y : backends) {
      std::size_t n = 0, same = 0;
      for (const auto& [key, m] : by_run) {
        const auto ix = m.find(x), iy = m.find(y);
        if (ix == m.end() || iy == m.end()) continue;
        const Outcome ox = outcome(*ix->second), oy = outcome(*iy->second);
        if (!is_judged(ox) || !is_judged(oy)) continue;
        ++n;
        same += is_failure(ox) == is_failure(oy) ? 1 : 0;
      }
      md << " " << (x == y || n == 0 ? std::string() : share_with_interval(same, n)) << " |";
    }
    std::size_t alone = 0;
    for (const auto& [key, m] : by_run) {
      const auto ix = m.find(x);
      if (ix == m.end() || !is_failure(outcome(*ix->second))) continue;
      bool others_fine = m.size() > 1;
      for (const auto& [b, r] : m) {
        if (b == x) continue;
        const Outcome o = outcome(*r);
        if (is_judged(o) && is_failure(o)) others_fine = false;
      }
      alone += others_fine ? 1 : 0;
    }
    md << " " << alone << " |\n";
  }
  md << "\n";

  md << corpus_report(rows, backends);
  return md.str();
}

}  // namespace mk::experiments
