// The sweep runner: every case x op x regular x kernel, against the exact reference, in
// worker processes watched by the parent so that a crash or a hang costs one run, not the
// sweep. [MK89 §3.3] (inexact arithmetic may fail; the failures are the data)
// Preconditions: kernels named in the options exist in mk::kernel_names(); the process is
// single-threaded when run_sweep forks its workers.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/polygon.hpp"
#include "experiments/case.hpp"
#include "experiments/results.hpp"

namespace mk::experiments {

struct RunOptions {
  // Back ends: names from mk::kernel_names() and from peer_names() (peers/peers.hpp).
  std::vector<std::string> kernels;
  std::vector<Operation> ops{Operation::intersection, Operation::union_, Operation::difference,
                             Operation::symmetric_difference};
  std::vector<bool> regular{true, false};
  int jobs = 1;
  double timeout_seconds = 30;  // per run (the reference and each kernel run separately)
  std::size_t memory_mb = 0;    // address-space limit per worker; 0: none
  bool isolate = true;          // run cases in forked workers (false: in this process)
  bool progress = false;        // a progress line on stderr
  // The reference uses the paper's sorted EF table and all-pairs search on cases up to
  // this many input vertices (a partly independent check of the rational kernel), the
  // hash table and sweep above it.
  std::size_t paper_reference_limit = 600;
  // Peers run on the regular operations of generated cases whose plan index is a multiple
  // of peer_every and whose size is at most peer_max_size (0: any), and on every external
  // case (reported, --cases): the default sweep samples them, --full runs them all.
  std::size_t peer_every = 1;
  std::size_t peer_max_size = 0;
  // How each kernel's written output is rounded (columns nearest_valid, certified_*):
  // certified by default, or snapped onto this grid (mk::BooleanOptions::grid) when set.
  RoundingMode rounding = RoundingMode::certified;
  std::string grid;
  // Tests only: called in the worker before each kernel run, e.g. to crash or hang there.
  std::function<void(const std::string& kernel, const CaseSpec& spec)> fault_injection;
};

struct IndexedCase {
  std::uint64_t index = 0;  // position in the full plan
  CaseSpec spec;
};

// A part of a sweep for array jobs: cases index, index + count, index + 2 count, ...
struct Shard {
  std::size_t index = 0;
  std::size_t count = 1;
};
// Parses "i/N" (0 <= i < N); throws std::invalid_argument.
Shard parse_shard(const std::string& text);
std::vector<IndexedCase> select_shard(const std::vector<CaseSpec>& plan, Shard shard);

// The runs of one case in this process, from run slot `first_slot` on (slots enumerate
// (op, regular) groups, each the reference then every kernel). `on_generated(size)` is
// called once the case is built, `on_start(slot)` before each run, `on_row` after it with
// its CSV row.
void run_case(const IndexedCase& c, const RunOptions& options, std::size_t first_slot,
              const std::function<void(std::size_t)>& on_start, const std::function<void(const ResultRow&)>& on_row,
              const std::function<void(std::size_t)>& on_generated = {});

// As run_case, on a case built elsewhere (a generator written in Python, through the
// module): `c.spec` names it in the rows, `built` holds its inputs.
void run_built_case(const IndexedCase& c, const Case& built, const RunOptions& options, std::size_t first_slot,
                    const std::function<void(std::size_t)>& on_start,
                    const std::function<void(const ResultRow&)>& on_row);

std::size_t slot_count(const RunOptions& options);

// The oracle_agrees column: for each (case, op, regular) with a cgal_epeck run, every exact
// kernel's row says whether its result agrees exactly with CGAL Epeck's. The kernel's output
// equals the reference vertex for vertex (exact_match) and the cgal_epeck verdict compares the
// reference with CGAL exactly (exact area, empty symmetric difference), so agreement is
// exact_match and exact_area; a disagreement carries the independent point check's finding.
void fill_oracle_agreement(std::vector<ResultRow>& rows);

struct SweepStats {
  std::size_t cases = 0;
  std::size_t rows = 0;
  double seconds = 0;
};

// Runs the cases (in parallel worker processes unless !options.isolate) and returns every
// row, sorted by case and slot. When `partial_csv` is not empty, rows are also appended to
// it as they arrive, so a killed sweep keeps what it measured.
std::vector<ResultRow> run_sweep(const std::vector<IndexedCase>& cases, const RunOptions& options,
                                 const std::string& partial_csv, SweepStats* stats = nullptr);

}  // namespace mk::experiments
