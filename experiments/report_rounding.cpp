// Rounded-output validity tables (see report_rounding.hpp). [BRIEF §6a]
// Preconditions: see report_rounding.hpp.
#include "experiments/report_rounding.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "experiments/statistics.hpp"

namespace mk::experiments {

namespace {

struct RoundingTally {
  std::size_t runs = 0, nearest_invalid = 0, snapped = 0, certified_invalid = 0, geos_checked = 0, geos_invalid = 0;
  double worst_displacement = 0;
  void add(const ResultRow& r) {
    ++runs;
    nearest_invalid += r.nearest_valid == false;
    snapped += r.certified_snapped == true;
    certified_invalid += r.certified_valid == false;
    geos_checked += r.geos_valid.has_value();
    geos_invalid += r.geos_valid == false;
    if (r.snap_displacement) worst_displacement = std::max(worst_displacement, *r.snap_displacement);
  }
};

std::string displacement_cell(const RoundingTally& t) {
  if (t.snapped == 0) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", t.worst_displacement);
  return buf;
}

std::string geos_cell(const RoundingTally& t) {
  if (t.geos_checked == 0) return "-";
  return std::to_string(t.geos_invalid) + " of " + std::to_string(t.geos_checked);
}

void table(std::ostringstream& md, const std::string& label, const std::map<std::string, RoundingTally>& by) {
  md << "| " << label
     << " | runs | nearest invalid | certified: snapped | certified: invalid | certified: GEOS invalid | largest move "
        "(grid units) |\n"
     << "|---|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& [name, t] : by) {
    md << "| " << name << " | " << t.runs << " | " << rate_with_interval(t.nearest_invalid, t.runs) << " | " << t.snapped
       << " | " << t.certified_invalid << " | " << geos_cell(t) << " | " << displacement_cell(t) << " |\n";
  }
  md << "\n";
}

}  // namespace

std::string rounding_report(const std::vector<ResultRow>& rows, const std::vector<Artefact>& artefacts) {
  std::map<std::string, RoundingTally> by_kernel, by_generator;
  for (const auto& r : rows) {
    if (!r.nearest_valid || !r.certified_valid) continue;
    by_kernel[r.kernel].add(r);
    if (r.kernel == "exact") by_generator[r.generator].add(r);
  }
  if (by_kernel.empty()) return {};
  std::ostringstream md;
  md << "## Rounded output valid\n\n"
     << "Whether the written polygons are valid (OGC, checked exactly) when every vertex is rounded to its nearest "
        "double (`--rounding nearest`) and with certified rounding (the default: the nearest doubles when valid, "
        "else snap rounding onto the power-of-two grid at the scale of the largest coordinate). Snap rounding needs "
        "a result whose edges do not cross, so the rounded kernels are left as computed: their certified column "
        "counts the nearest doubles. GEOS's `isValid` is asked about the exact kernels' written polygons, scaled exactly by "
        "a power of two into its range, unless their coordinates spread over more than 2^400 (\"invalid of checked\"; "
        "`-`: not asked). Columns "
        "`nearest_valid`, `certified_snapped`, `certified_valid`, `geos_valid`, `snap_displacement` of the CSV.\n\n";
  table(md, "kernel", by_kernel);
  md << "Per generator, kernel `exact`:\n\n";
  table(md, "generator", by_generator);
  std::vector<const Artefact*> pictures;
  for (const auto& a : artefacts) {
    if (a.kind == Artefact::Kind::snapping) pictures.push_back(&a);
  }
  if (!pictures.empty()) {
    md << "Before and after snapping (kernel `exact`, the smallest snapped cases of each generator): the result with "
          "every vertex rounded to its nearest double and why that is not a valid polygon, beside the certified "
          "output with its grid and largest vertex move, and a zoom on the first vertex where they differ (grid "
          "points grey).\n\n"
       << "| generator | variant | params | seed | op | picture |\n|---|---|---|---:|---|---|\n";
    for (const Artefact* a : pictures) {
      const ResultRow& r = a->row;
      md << "| " << r.generator << " | " << r.variant << " | " << r.params << " | " << r.seed << " | " << r.op
         << (r.regular ? "" : " (non-regular)") << " | [picture](" << a->path << ") |\n";
    }
    md << "\n";
  }
  return md.str();
}

}  // namespace mk::experiments
