// Pictures of snapped results (see snapping_pictures.hpp): the run picker and the picture,
// drawn with failure_picture's panels and zoom. [Ho99] [HP02] [BRIEF §6a]
// Preconditions: see snapping_pictures.hpp.
#include "experiments/snapping_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "api/mkbool.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/ogc_validity.hpp"
#include "experiments/operations.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/pictures.hpp"

namespace mk::experiments {

namespace {

// The polygons as written, as the cycles the panels draw (shells and holes), with the
// non-regular parts as they are.
Output as_written(const Output& o) {
  Output w;
  for (const OgcPolygon& p : o.polygons) {
    w.irreducible.push_back({p.shell, {}, PolygonType::island});
    for (const Ring& h : p.holes) w.irreducible.push_back({h, {}, PolygonType::hole});
  }
  w.dangling_edges = o.dangling_edges;
  w.isolated_points = o.isolated_points;
  return w;
}

// The spacing of a power-of-two grid written "2^e" (RoundingReport::grid); 0 for another
// grid (a user's "p/q" is not a double: its points are not marked).
double power_of_two_spacing(const std::string& grid) {
  if (grid.rfind("2^", 0) != 0) return 0;
  try {
    std::size_t used = 0;
    const int e = std::stoi(grid.substr(2), &used);
    return used == grid.size() - 2 ? std::ldexp(1.0, e) : 0;
  } catch (const std::exception&) {
    return 0;
  }
}

std::string nearest_title(const Output& nearest) {
  if (nearest.rounded_valid != false) return "nearest doubles: valid";
  std::string why;
  const OgcValidity v = check_ogc_validity<ExactKernel>(nearest.polygons);
  why = v.valid() ? "a dangling edge or point collapses" : v.why();
  std::string geos_why;
  if (geos_is_valid(nearest.polygons, &geos_why) == false) why += "; GEOS: " + geos_why;
  return "nearest doubles: invalid (" + why + ")";
}

std::string certified_title(const Output& o) {
  const RoundingReport& r = o.rounding;
  const std::string parts = ", " + std::to_string(o.polygons.size()) + (o.polygons.size() == 1 ? " polygon" : " polygons");
  if (!r.snapped) return "certified: not snapped" + parts + (r.valid ? "" : ", INVALID");
  char move[32] = "";
  if (r.max_displacement) std::snprintf(move, sizeof move, "%.3f", *r.max_displacement);
  return "certified: snapped to grid " + r.grid + ", largest move " + move + " grid step" + parts +
         (r.valid ? "" : ", INVALID" + (r.failure.empty() ? std::string() : " (" + r.failure + ")"));
}

}  // namespace

std::vector<const ResultRow*> snapped_runs_to_picture(const std::vector<ResultRow>& rows, std::size_t per_generator) {
  std::map<std::string, std::vector<const ResultRow*>> by_generator;
  for (const auto& r : rows) {
    if (r.kernel == "exact" && r.certified_snapped == true) by_generator[r.generator].push_back(&r);
  }
  std::vector<const ResultRow*> out;
  for (auto& [generator, list] : by_generator) {
    // Smallest cases first; at equal size, runs where a vertex moved (rather than a sliver
    // snapped away whole), the largest move first.
    const auto moved = [](const ResultRow* r) { return r->snap_displacement.value_or(0); };
    std::stable_sort(list.begin(), list.end(), [&](const ResultRow* x, const ResultRow* y) {
      if (x->size != y->size) return x->size < y->size;
      if (moved(x) != moved(y)) return moved(x) > moved(y);
      return x->case_index < y->case_index;
    });
    std::set<std::uint64_t> cases;  // one picture per case
    for (const ResultRow* r : list) {
      if (cases.size() >= per_generator) break;
      if (cases.insert(r->case_index).second) out.push_back(r);
    }
  }
  return out;
}

std::string snapping_picture(const Case& c, Operation op, bool regular, const std::string& kernel) {
  BooleanOptions options{op, regular, kernel};
  options.area = false;
  options.rounding = RoundingMode::nearest;
  const Output nearest = run_operation(c, options).output;
  options.rounding = RoundingMode::certified;
  const Output certified = run_operation(c, options).output;
  const double spacing = certified.rounding.snapped ? power_of_two_spacing(certified.rounding.grid) : 0;
  // Three grid steps each side: the moved vertices and the pixels they went to. Moves are
  // below a grid step (about an ulp of the largest coordinate): never visible unzoomed.
  const ZoomOptions zoom{"nearest doubles", "certified output", 3 * spacing, spacing, true};
  return failure_picture(c.a, c.b, as_written(nearest), nearest_title(nearest), as_written(certified),
                         certified_title(certified), zoom);
}

}  // namespace mk::experiments
