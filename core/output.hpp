// A kernel-independent view of a Boolean result, for writers and users: the irreducible
// result polygons with their types [MK89 §3.1 step 6] and the same region assembled into
// OGC polygons-with-holes [MK89 §2.2, inclusion forest].
// Preconditions: produced by mk::boolean_op / mk::to_output; coordinates rounded to nearest.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/polygon.hpp"

namespace mk {

// One irreducible result polygon: a cycle of 3+ vertices, a two-sided segment (2 vertices)
// or a one-sided point (1 vertex). `exact` holds "p/q" strings per coordinate (x then y)
// for exact kernels, and is empty otherwise.
struct OutputIrreducible {
  std::vector<Point> vertices;
  std::vector<std::string> exact;  // 2 * vertices.size() strings, or empty
  PolygonType type = PolygonType::island;
};

// How the written coordinates were obtained [BRIEF §6a]: `nearest` rounds every vertex to
// its nearest doubles (and says whether that is valid); `certified` (the default) does that
// when the result so rounded is valid and snap-rounds it onto a grid otherwise, or always
// onto the grid the user gives.
enum class RoundingMode : unsigned char { certified, nearest };

struct RoundingReport {
  RoundingMode mode = RoundingMode::certified;
  bool snapped = false;      // the written coordinates are a snap rounding
  std::string grid;          // its grid's spacing ("2^-52", or the exact "p/q" given); empty otherwise
  bool user_grid = false;    // the grid was asked for
  bool regridded = false;    // the user grid's points, rounded to doubles, were not valid: snapped again
                             // on the grid of doubles at the scale of the largest coordinate
  std::optional<double> max_displacement;  // largest vertex move, in units of the grid (snapped only)
  std::size_t hot_pixels = 0;
  std::size_t incidences = 0;  // edge-hot-pixel incidences besides the edges' ends
  int rounds = 0;              // iterated snap rounding's extra rounds
  bool valid = true;           // the written polygons are valid (OGC, checked exactly)
  // Non-empty when snap rounding could not produce a certified output (its own exact
  // self-check failed: a defect, reported with the nearest doubles written and valid false).
  std::string failure;
};

struct Output {
  std::vector<OutputIrreducible> irreducible;
  // The regular (area) part as OGC polygons with holes; empty when unbounded.
  MultiPolygon polygons;
  // Non-regular parts: dangling edges (two-sided) and isolated points (one-sided).
  std::vector<std::pair<Point, Point>> dangling_edges;
  std::vector<Point> isolated_points;
  // True when the result region is unbounded (its outermost cycles are hole-like): it
  // cannot be written as WKT or GeoJSON, only in the native format.
  bool unbounded = false;
  // Whether the coordinates rounded to the nearest doubles form a valid output (OGC validity
  // of `polygons` as rounded, and two-sided parts of two distinct points), checked exactly.
  std::optional<bool> rounded_valid;
  // How `polygons`, `dangling_edges` and `isolated_points` were rounded. When snapped they
  // are the snap rounding, while `irreducible` keeps the exact result's cycles (rounded to
  // nearest, with their exact coordinates).
  RoundingReport rounding;
};

}  // namespace mk
