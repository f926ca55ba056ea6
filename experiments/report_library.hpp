// The report's comparison of libraries and kernels on the same runs: one outcome scale for
// both (exact, rounding only, wrong, invalid output, exception, crash, timeout, refused),
// per-run and per-case rates with 95% Wilson intervals, the failure map per generator,
// breakdowns by operation and regularity, pairwise agreement, the independent-oracle
// summary of the exact kernels, and the reported corpus case by case with its citations.
// [BRIEF §5] [MK89 §3.3]
// Preconditions: rows from run_sweep (kernels and peers); peers run regular operations only.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "experiments/results.hpp"

namespace mk::experiments {

enum class Outcome : unsigned char {
  exact,           // kernels: exact_match; peers: exact_area
  rounding_only,   // symmetric difference within the rounding bound (rounding_bound column)
  wrong,           // beyond it (or unbounded against bounded)
  invalid_output,  // not a valid polygon (our exact check, or GEOS isValid for peers)
  exception,       // the library or kernel threw (mkbool's KernelFailure, GEOS TopologyException)
  crash,
  timeout,
  refused,      // mkbool refused an external input outside its domain
  unjudged,     // no exact comparison possible (no reference, or too many polygons to overlay)
  unsupported,  // the back end cannot express the input (hole-type polygons for OGC libraries)
};
inline constexpr Outcome all_outcomes[] = {Outcome::exact,     Outcome::rounding_only, Outcome::wrong,
                                           Outcome::invalid_output, Outcome::exception, Outcome::crash,
                                           Outcome::timeout,   Outcome::refused,   Outcome::unjudged,
                                           Outcome::unsupported};
std::string_view outcome_name(Outcome o);
Outcome outcome(const ResultRow& row);
// wrong, invalid_output, exception, crash or timeout.
bool is_failure(Outcome o);

// The Markdown sections (empty when the rows hold no peer and no external case).
std::string library_report(const std::vector<ResultRow>& rows);

// The reported corpus and the user's cases, one line per case with what each back end
// gives on the operation the case names (report_corpus.cpp); empty without such cases.
std::string corpus_report(const std::vector<ResultRow>& rows, const std::vector<std::string>& backends);

// Text fit for a Markdown table cell (no '|', no line breaks).
std::string markdown_cell(std::string s);

}  // namespace mk::experiments
