// What the command reports about one operation: the --stats line and the exact validity
// of the rounded output. [MK89 §3.3] (non-orientable rounded output) [Sh97 §4.2] (stages)
// Preconditions: `result` comes from mk::compute.
#pragma once

#include <string>

#include "api/mkbool.hpp"
#include "arithmetic/predicates_counters.hpp"

namespace mk::cli {

// Whether the output's rounded coordinates form a valid output, decided exactly: exact
// kernels have checked it already (Output::rounded_valid); for inexact kernels it is
// checked here, so that a rounded kernel's broken result shows up as data.
bool is_output_valid(const Output& output);

// One JSON object, no newline: kernel, op_ns, vertices_in, crossings, vertices_out,
// rounded_valid (null for inexact kernels), area (null when unbounded or beyond the
// largest double), area_beyond_double (true for the latter), area_exact (null for inexact
// kernels or when unbounded), and, in builds with MK_COUNTERS, "predicates": per method and
// predicate, the calls and how many of them each stage decided. `counters` are those of the
// whole mk::compute call, so they include the exact check of the rounded output.
std::string stats_json(const BooleanOutput& result, const PredicateCounters& counters);

}  // namespace mk::cli
