// The command's batch form: JSON Lines in, one result line per case out, for experiments
// and conformance runs. [MK89 §3.2] [MK89 §2.3] (operations; symmetric difference added)
// Preconditions: the kernel name is one of mk::kernel_names() (checked while parsing).
#pragma once

#include <string>

#include "core/output.hpp"

namespace mk::cli {

struct BatchOptions {
  std::string input;   // a JSON Lines file, or `-` for standard input
  std::string kernel;  // empty: mk::default_kernel()
  bool regular = true;
  // Compute each line's "area_exact" (a line's own "area_exact": false leaves it out too):
  // on results with many crossing points it costs more than the operation.
  bool area_exact = true;
  std::string output;  // empty: standard output
  // Rounding of each line's result_wkt (a line's own "rounding" and "grid" override them).
  RoundingMode rounding = RoundingMode::certified;
  std::string grid;
  // Every line gets "result": the result in the native JSON form, with exact coordinates
  // from exact kernels (a line's own "exact_result" true or false overrides it).
  bool exact_result = false;
};

// Each non-blank input line is an object with "id" (any JSON value, echoed), "op"
// (intersection, union, difference, symdifference or xor), and the polygons as "a_wkt" and
// "b_wkt", or as "a" and "b" in the native JSON form (objects; coordinates may be exact
// rationals, and a line's "result" is such a polygon); other members are ignored, except
// "area_exact": false, which leaves that line's exact area out, "exact_result" (see
// BatchOptions), "rounding", "grid", and "fill_rule" (evenodd, nonzero, positive, negative or
// union), which reads a_wkt and b_wkt as any rings by that rule (regular batches only).
// Each gives one output line, in input order: id, op, kernel, result_wkt, area (null beyond
// the largest double), area_beyond_double, area_exact, valid, op_ns, line (1-based input
// line), and error when the
// case failed; a failed case never stops the batch. Returns the number of failed cases.
// Throws mk::InvalidInput when the batch file cannot be read, mk::cli::OutputError when the
// output cannot be written (the output file is then left untouched).
std::size_t run_batch(const BatchOptions& options);

}  // namespace mk::cli
