// The public library API: one call computes a Boolean operation of two polygons with a
// kernel chosen by name, and returns the kernel-independent Output.
// [MK89 §3.2] (procedure polygonoperation: inputs A, B, types, operation, regularity)
// Preconditions: none; invalid input raises mk::InvalidInput, inconsistent inexact
// arithmetic mk::KernelFailure.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/fill_rule.hpp"
#include "api/exact_polygon.hpp"
#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk {

// Names of the kernels built into this library, fastest exact one first.
std::vector<std::string_view> kernel_names();
// The kernel used when none is named: the fastest exact kernel built.
std::string_view default_kernel();
bool is_exact_kernel(std::string_view name);
// Kernels that repeat another with a different number type (rational-mp, rational-cpp: the
// rational kernel over Boost.Multiprecision's rationals): the same results, another cost.
bool is_number_type_variant(std::string_view name);

struct BooleanOptions {
  Operation op = Operation::intersection;
  bool regular = true;
  std::string kernel;  // empty: default_kernel()
  bool sorted_ef = false;  // the paper's sorted EF table instead of the hash table
  bool all_pairs = false;  // the paper's all-pairs intersection search
  bool area = true;        // BooleanStats::area: the area rounded to the nearest double
  bool area_exact = false;  // BooleanStats::area_exact (exact kernels): costs more than the
                            // operation on results with many crossing points
  // Output::irreducible[i].exact: the exact coordinates as "p/q" strings (exact kernels).
  bool exact_coordinates = false;
  // A fill rule reads each input's rings in the directions given, crossing themselves and
  // each other freely: its region is the closure of the points whose winding number the rule
  // accepts (Clipper's meanings). Regular output only. Unset: the paper's domain (rings may
  // touch, never cross; regions by nesting), exactly as without this option.
  std::optional<FillRule> fill_rule = std::nullopt;
  // Threads for the phases that run in parallel (candidate pairs, crossings, classification,
  // the two polygons' preparation); 0: every core. Results are the same, bit for bit, on
  // any number of threads.
  unsigned threads = 0;
  // How Output::polygons, dangling_edges and isolated_points are rounded to doubles
  // (Output::rounding says what was done). certified (default): the nearest doubles when
  // they form a valid output, else a snap rounding onto the power-of-two grid at the scale
  // of the largest coordinate; nearest: the nearest doubles, valid or not.
  RoundingMode rounding = RoundingMode::certified;
  // Snap rounding onto multiples of this spacing, always (certified mode): a positive
  // decimal ("0.001", "1e-3") or fraction ("1/3"), taken exactly. Empty: none.
  std::string grid = {};
};

struct BooleanStats {
  std::string kernel;
  std::int64_t op_ns = 0;  // the operation alone
  std::size_t vertices_in = 0;
  std::size_t crossings = 0;
  std::size_t vertices_out = 0;
  // Area of the result (regular part), correctly rounded to the nearest double; exact
  // kernels also give it as a reduced rational "p/q" or integer "p". Empty when unbounded
  // or not asked for (BooleanOptions::area, area_exact). An area larger than the largest
  // double (coordinates beyond about 1.3e154 can make one) is +infinity, as IEEE rounding
  // gives it, and area_beyond_double says so; area_exact still holds it exactly. Never NaN.
  std::optional<double> area;
  std::optional<std::string> area_exact;
  bool area_beyond_double = false;
  std::int64_t rounding_ns = 0;  // certified rounding after the operation (0 when not checked)
};

struct BooleanOutput {
  Output output;
  BooleanStats stats;
};

// Throws std::invalid_argument for an unknown kernel name. With options.fill_rule, the rings
// of A and B are read by the rule in their given directions (FillRule::union_ reads them as
// nonzero: see fill_rule_polygon); options.regular false gives the closed-set operation of
// the two regions' closures (their two- and one-sided parts where they only touch).
BooleanOutput compute(const Polygon& a, const Polygon& b, const BooleanOptions& options);

// The rings of an OGC multipolygon as a fill rule reads them: as given, or, for
// FillRule::union_, each shell turned counterclockwise and each hole clockwise (by the exact
// sign of its signed area; a ring of zero signed area is left as given), so that the nonzero
// rule gives the union of the parts, each its shell less its holes.
Polygon fill_rule_polygon(const MultiPolygon& mp, FillRule rule);

// N-ary operations on the parts of a multipolygon (a MULTIPOLYGON, a GeoJSON FeatureCollection,
// a file of one polygon per line), as one arrangement of all rings. options.op is not read;
// options.regular false gives the closed-set operation (intersection_all then keeps the edges
// and points where parts only touch).
// union_all: the closure of the points whose winding number over all rings together (after
//   fill_rule_polygon) the rule accepts; default rule union_, which gives the union of the
//   parts. Other rules read all rings at once, as Clipper's union of all paths does.
// intersection_all: the points in every part's region, each part read by the rule on its own
//   (default union_); costs one winding number per part and link of the arrangement.
// make_valid: the region of all rings by the rule (default evenodd), as a valid polygon.
BooleanOutput union_all(const MultiPolygon& parts, const BooleanOptions& options);
BooleanOutput intersection_all(const MultiPolygon& parts, const BooleanOptions& options);
BooleanOutput make_valid(const MultiPolygon& input, const BooleanOptions& options);
// The same over exact rational coordinates (for example an exact result fed back in, see
// exact_vertices). Polygons whose coordinates are all doubles go to the kernel asked for;
// others need an exact kernel over rationals: the default, "exact" and "rational" run the
// rational kernel (stats.kernel says so), "rational-mp" and "rational-cpp" themselves; the
// rounded kernels throw std::invalid_argument, as does a fill rule (fill rules read doubles).
BooleanOutput compute(const ExactPolygon& a, const ExactPolygon& b, const BooleanOptions& options);

// The exact vertices of a result cycle (asked for with BooleanOptions::exact_coordinates).
// Throws std::invalid_argument when the cycle has no exact coordinates.
std::vector<RationalPoint> exact_vertices(const OutputIrreducible& cycle);

// The exact result as a polygon of the paper's model, ready to be an operand: every cycle
// as a ring (those of 3 or more vertices nest by parity; dangling edges are rings of 2
// vertices, isolated points rings of 1, which the model reads as parts of the point set),
// type hole when unbounded. Throws std::invalid_argument when the output has no exact
// coordinates, or is unbounded with dangling edges or isolated points (a hole-type
// polygon's degenerate rings would not add their points).
ExactPolygon exact_result(const Output& output);

}  // namespace mk
