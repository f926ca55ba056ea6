// Pictures of results before and after snapping (issue 12): which runs of a sweep to draw
// (kernel `exact`, certified rounding snapped, the smallest cases of each generator), and
// the picture of one: the result with every vertex rounded to its nearest double (and why
// that is not a valid polygon) beside the certified output on its grid, with a zoom on the
// first vertex where they differ. [Ho99] [HP02] [BRIEF §6a]
// Preconditions: rows come from run_sweep; the case's kernel is one of mk::kernel_names().
#pragma once

#include <string>
#include <vector>

#include "core/polygon.hpp"
#include "experiments/case.hpp"
#include "experiments/results.hpp"

namespace mk::experiments {

// Runs of kernel `exact` whose output certified rounding snapped: for each generator the
// `per_generator` smallest cases (input size; at equal size those with the largest vertex
// move, then plan order), one run per case (the one with the largest move).
std::vector<const ResultRow*> snapped_runs_to_picture(const std::vector<ResultRow>& rows, std::size_t per_generator);

// The SVG: left, A, B and the result rounded to the nearest doubles (titled with the exact
// OGC check's reason when invalid, and GEOS's where built); right, A, B and the output as
// certified rounding writes it (titled with its grid and largest vertex move); a zoom on
// the first difference that marks the grid's points. Computes the case's operation twice
// (operations.hpp: pair or set case, with its fill rule).
std::string snapping_picture(const Case& c, Operation op, bool regular, const std::string& kernel);

}  // namespace mk::experiments
