// Verdicts on a peer library's result against the exact reference: exact_area,
// rounding_only (symmetric difference within the rounding bound), wrong, invalid_output
// (GEOS's isValid and our exact OGC check, both reported), and for disagreements of an
// exact library an independent point check that says which side is wrong.
// [MK89 §3.3] (rounded results) [BRIEF §5] (verdicts) [OGC06-103 §6.1.11]
// Preconditions: the reference is RationalKernel's regular result on the same A, B, op.
#pragma once

#include <optional>
#include <string>

#include "core/output.hpp"
#include "experiments/case.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/verdict.hpp"

namespace mk::experiments {

// The distance a correct floating-point library may move a vertex: 2^-50 times the largest
// input coordinate magnitude (8 units in the last place of a double, relative to it).
double input_resolution(const Polygon& a, const Polygon& b);

// The rounding bound on the symmetric-difference area of a result against the exact one
// when every vertex of either moves by at most `delta`: each edge then sweeps at most
// delta times its length on each side, so the bound is 2 delta (P_exact + P_result), P the
// perimeters (of area rings, in doubles).
double rounding_bound(double delta, double perimeter_exact, double perimeter_result);
double perimeter(const std::vector<ExactCycle>& cycles);

struct PeerAssessment {
  Assessment assessment;          // verdict, symmetric-difference area, area error, note
  std::optional<bool> geos_valid;  // GEOS's isValid of the result (doubles)
  std::optional<bool> exact_valid;  // is_valid_ogc_exact of the result (doubles)
  std::optional<double> bound;      // the rounding bound applied
};

// `delta`: input_resolution of the case. With no reference (mkbool refused the input) the
// verdict is unjudged or invalid_output.
PeerAssessment assess_peer(const PeerOutput& output, const ExactResult* reference, double delta);

// Which of two exact results is wrong, by a point strictly inside their symmetric
// difference whose location in A, B and both results is decided by exact crossing parity
// written here (not the core's): "mkbool" when the reference contradicts the set
// operation there, "other" when the other result does, empty when not decidable.
struct PointCheck {
  std::string wrong;        // "mkbool", "other" or empty
  std::string explanation;  // the point and the locations
};
PointCheck independent_point_check(const Polygon& a, const Polygon& b, Operation op, const ExactResult& reference,
                                   const std::vector<ExactCycle>& other, bool other_unbounded);

// The output's rings as cycles of exact points (islands for shells, holes for holes).
std::vector<ExactCycle> peer_cycles(const PeerOutput& output);

// The output as mkbool's Output (shells counterclockwise islands, holes clockwise), for pictures.
Output peer_as_output(const PeerOutput& output);

// A peer on a case's inputs, with their OGC forms (as given for external cases, from the
// rings' nesting otherwise).
PeerOutput run_peer_on_case(const std::string& peer, const Case& c, Operation op);

// Whether a verdict is a failure worth a picture or a regression case: not exact_match,
// exact_area, rounding_only, refused, unjudged, unsupported or invalid_input.
bool is_failure(Verdict v);

}  // namespace mk::experiments
