// The report's section on rounded output (issue 12): per kernel and per generator, how many
// results rounded to the nearest doubles are invalid polygons, how many certified rounding
// snap-rounded, how many written outputs are still invalid (the goal: none for the exact
// kernels), by the exact check and by GEOS's isValid, and the largest vertex displacement
// in grid units. [Ho99] [HP02] [BRIEF §6a]
// Preconditions: rows from run_sweep; rows without the rounding columns are left out.
#pragma once

#include <string>
#include <vector>

#include "experiments/results.hpp"

namespace mk::experiments {

// The Markdown section, empty when no row has the rounding columns.
std::string rounding_report(const std::vector<ResultRow>& rows);

}  // namespace mk::experiments
