// One CSV row per run (case x op x regular x kernel) and the CSV reader and writer; the
// column list is the schema documented in experiments/README.md.
// [MK89 §3.2] (a run: polygons A, B, operation, regularity, arithmetic)
// Preconditions: none; the reader rejects files whose header is not this schema.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/verdict.hpp"

namespace mk::experiments {

struct ResultRow {
  std::uint64_t case_index = 0;  // position in the sweep plan (shards keep global indices)
  std::string generator;
  std::string variant;
  std::string params;  // "k=-3;n=256"
  std::uint64_t seed = 0;
  std::uint64_t size = 0;  // input vertices of A and B together
  std::string op;          // intersection, union, difference, xor
  bool regular = true;
  std::string kernel;  // a name from mk::kernel_names() or peer_names(), or "reference"
                       // when the reference itself failed on this (case, op, regular)
  Verdict verdict = Verdict::exact_match;
  std::optional<double> area_error;
  std::optional<double> symdiff_area;
  std::optional<double> exact_area;
  std::optional<std::int64_t> op_ns;
  std::optional<std::int64_t> predicate_calls;
  std::optional<std::int64_t> predicate_fallbacks;
  // The calls each stage decided, "stage=n;stage=n" in stage order (predicates_counters.hpp),
  // stages that decided none left out; empty without counters.
  std::string predicate_stages;
  std::optional<std::int64_t> vertices_in;
  std::optional<std::int64_t> crossings;
  std::optional<std::int64_t> vertices_out;
  std::string message;  // error text or the first difference found
  // The rounding bound on symdiff_area for rounding_only (peer_verdict.hpp), where measured.
  std::optional<double> rounding_bound;
  // Exact kernels: whether the result agrees exactly (area and empty symmetric difference)
  // with CGAL Epeck's on the same run; empty where CGAL did not run or gave no result.
  std::optional<bool> oracle_agrees;
  // Peers: GEOS's isValid and the exact OGC check of the result (ogc.hpp).
  std::optional<bool> geos_valid;
  std::optional<bool> exact_valid;
  // mkbool's kernels (issue 12): whether the result rounded to the nearest doubles is valid
  // (exact OGC check), whether certified rounding (the default) snap-rounded it, whether
  // the written output is valid, and the largest vertex move in grid units when snapped.
  std::optional<bool> nearest_valid;
  std::optional<bool> certified_snapped;
  std::optional<bool> certified_valid;
  std::optional<double> snap_displacement;
};

// The schema, in column order.
const std::vector<std::string_view>& csv_columns();

std::string csv_header();
std::string to_csv(const ResultRow& row);
// Throws std::runtime_error naming the line when a row does not parse.
ResultRow parse_csv_row(std::string_view line);

// Reads one results CSV (header checked).
std::vector<ResultRow> read_results(const std::string& path);
// Every DIR/results*.csv, in file-name order.
std::vector<ResultRow> read_results_dir(const std::string& dir);

}  // namespace mk::experiments
