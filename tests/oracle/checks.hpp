// One operation checked against every independent reference: `exact` must equal `rational`
// exactly, a regular result must be the region CGAL Epeck gives (symmetric difference empty,
// exact areas equal), and a non-regular one must agree with the membership oracle at every
// sample point. Shared by the differential test and the regression replay.
// [BRIEF §1] [BRIEF §3] (exact kernels agree on every input)
// Preconditions: A and B in mkbool's input domain (InvalidInput otherwise, from mkbool).
#pragma once

#include <random>
#include <string>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/boolean_op.hpp"
#include "tests/oracle/cgal_reference.hpp"
#include "tests/oracle/membership.hpp"

namespace mk::oracle {

// CGAL 5.5's Epeck decides the type of a line-line intersection on its interval
// approximation, which overflows for coordinates beyond about 2^340: two crossing edges
// then have no intersection, and Arr_segment_traits_2 fails an assertion (a segmentation
// fault in Release builds; CgalFaults.LineCrossingBeyondTheIntervalRange... shows it). So
// CGAL is handed every configuration scaled by the power of two that brings its largest
// coordinate into [1, 2): a similarity, which the set operations commute with, so mkbool's
// result (computed on the original coordinates) is scaled the same way before comparing,
// and its area by the square.
struct Frame {
  Q scale = 1;

  static Frame of(const Region& a, const Region& b);
  QPoint to_cgal(const QPoint& p) const { return {p.x * scale, p.y * scale}; }
  QPoint from_cgal(const QPoint& p) const { return {p.x / scale, p.y / scale}; }
  Region to_cgal(const Region& r) const;
};

// The inputs as every reference sees them, made once per pair.
struct References {
  Region a, b;
  Frame frame;
  CgalSet cgal_a, cgal_b;

  static References of(const Polygon& a, const Polygon& b);
};

// mkbool's result as a region of the paper's model (exact coordinates; unbounded: the
// complement), and its typed area (islands add, holes subtract: for an unbounded result,
// minus the area of its complement).
Region result_region(const BooleanResult<RationalKernel>& r);
Q typed_result_area(const BooleanResult<RationalKernel>& r);

struct Tally {
  long operations = 0;
  long regular_vs_cgal = 0;
  SampleCounts nonregular_points;
  long cgal_faults = 0;  // CGAL's result contradicted by the oracle, mkbool's confirmed
};

// Runs `opt` on A and B with both exact kernels and checks the result (see the top of this
// file). On a difference from CGAL, the oracle decides at a point where the two differ:
// CGAL contradicted and mkbool confirmed is counted as CGAL's fault (and printed with
// `what`), anything else is a failure. Returns the failure, or empty.
std::string check_operation(const Polygon& a, const Polygon& b, const References& refs, const Options& opt,
                            std::mt19937_64& rng, Tally& tally, const std::string& what);

}  // namespace mk::oracle
