// The report's section on rounded output (issue 12): per kernel and per generator, how many
// results rounded to the nearest doubles are invalid polygons, how many certified rounding
// snap-rounded, how many written outputs are still invalid (the goal: none for the exact
// kernels), by the exact check and by GEOS's isValid, the largest vertex displacement in
// grid units, and links to the pictures of snapped results. [Ho99] [HP02] [BRIEF §6a]
// Preconditions: rows from run_sweep; rows without the rounding columns are left out.
#pragma once

#include <string>
#include <vector>

#include "experiments/artefacts.hpp"
#include "experiments/results.hpp"

namespace mk::experiments {

// The Markdown section, empty when no row has the rounding columns. Artefacts of kind
// snapping are listed in it.
std::string rounding_report(const std::vector<ResultRow>& rows, const std::vector<Artefact>& artefacts = {});

}  // namespace mk::experiments
