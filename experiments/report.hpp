// The report of a sweep: DIR/README.md with verdict rates per kernel and generator, time
// relative to the double kernel, PNG plots (made by plots.py with /usr/bin/python3) and
// links to the failure pictures and regression cases. [MK89 §3.3]
// Preconditions: DIR holds results*.csv from run or merge (and optionally sweep.txt and
// artefacts.csv).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "experiments/artefacts.hpp"
#include "experiments/results.hpp"

namespace mk::experiments {

struct ReportOptions {
  bool plots = true;  // run the plot script (off in unit tests that need no Python)
  std::string python = "/usr/bin/python3";
};

// Writes DIR/README.md (and DIR/plots/*.png when plots are on). Returns the README path.
std::string write_report(const std::string& dir, const ReportOptions& options);

// The Markdown text alone, from rows, artefacts and the sweep description lines.
std::string report_markdown(const std::vector<ResultRow>& rows, const std::vector<Artefact>& artefacts,
                            const std::vector<std::string>& sweep_lines, const std::vector<std::string>& plots);

// The section "Cost of exactness by fallback strategy" (report_fallbacks.cpp).
void fallback_section(std::ostream& md, const std::vector<ResultRow>& rows);

// The section "Fill rules and union-all sets" (report_sets.cpp): per fill or set generator,
// kernel and regularity, correct / wrong / error counts and time; empty without such rows.
std::string fill_and_set_report(const std::vector<ResultRow>& rows);

// Where plots.py is: $MK_EXPERIMENT_PLOTS, next to the executable, or in the source tree.
std::string plot_script_path();

}  // namespace mk::experiments
