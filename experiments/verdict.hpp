// The exact reference result and the verdict on one kernel's output against it:
// exact_match, valid_different (with the exact area of the symmetric difference) or
// invalid_output; error, timeout and crash come from the runner.
// [MK89 §3.3] (numerical accuracy; non-orientable rounded output) [MK89 §3.1 step 6]
// (irreducible result polygons and their types)
// Preconditions: the reference comes from RationalKernel on the same A, B, op, regular.
#pragma once

#include <gmpxx.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/fill_rule.hpp"
#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk::experiments {

enum class Verdict : unsigned char {
  exact_match,      // the same irreducible polygons, types and vertices (rounded, or exact)
  valid_different,  // a valid output, but not the exact result
  invalid_output,   // rounded output not valid: crossing/overlapping edges, collapsed ring,
                    // or a ring whose orientation contradicts its island/hole type
  error,            // the kernel threw (mk::KernelFailure or any other exception)
  timeout,          // the run exceeded the time limit and was killed
  crash,            // the process running the case died (signal)
  invalid_input,    // the reference rejected the input: a generator bug, not a kernel's
  // Verdicts of peer libraries (peer_verdict.hpp), whose results are never exact vertex for
  // vertex, and of runs on external cases (reported, --cases):
  exact_area,     // the exact area equals the exact result's and their symmetric difference is empty
  rounding_only,  // symmetric difference with the exact result within the rounding bound
  wrong,          // beyond it
  exception,      // the library threw or reported an error
  refused,        // mkbool refused the external input (outside its domain, e.g. self-crossing)
  unjudged,       // no exact result to compare with (mkbool refused the input); output valid
  unsupported,    // the back end cannot express the input (a hole-type polygon for OGC libraries)
};
inline constexpr Verdict all_verdicts[] = {Verdict::exact_match, Verdict::valid_different, Verdict::invalid_output,
                                           Verdict::error,       Verdict::timeout,         Verdict::crash,
                                           Verdict::invalid_input, Verdict::refused};
inline constexpr Verdict peer_verdicts[] = {Verdict::exact_area, Verdict::rounding_only, Verdict::wrong,
                                            Verdict::invalid_output, Verdict::exception, Verdict::timeout,
                                            Verdict::crash, Verdict::unjudged, Verdict::unsupported};

std::string_view verdict_name(Verdict v);
std::optional<Verdict> parse_verdict(std::string_view name);

struct ExactCycle {
  PolygonType type = PolygonType::island;
  std::vector<RationalPoint> vertices;
};

struct ExactResult {
  std::vector<ExactCycle> cycles;
  bool unbounded = false;
  mpq_class area;  // islands minus holes over the area cycles; 0 when unbounded
  Output output;   // the same result rounded, as kernels report it (pictures, comparison)
};

// RationalKernel on A op B. With `paper_variants` it uses the paper's sorted EF table and
// all-pairs intersection search, so that the `rational` kernel run through the API (hash
// table, sweep) is checked against a partly independent path.
// With a fill rule (cases of the fill generators), RationalKernel on the rings read by the
// rule, through the library (paper_variants: all-pairs search).
ExactResult exact_reference(const Polygon& a, const Polygon& b, Operation op, bool regular, bool paper_variants,
                            std::optional<FillRule> fill_rule = std::nullopt);
// The ExactResult of an exact kernel's output asked for with exact coordinates.
ExactResult exact_result_of(Output output);

struct Assessment {
  Verdict verdict = Verdict::exact_match;
  std::optional<double> symdiff_area;  // exact area of output XOR reference, rounded
  std::optional<double> area_error;    // symdiff_area / |exact area|, or absolute if that is 0
  std::string note;                    // the first difference found, or why output is invalid
};

// assess() measures area errors of outputs with at most this many result polygons
// (kernel's and reference's together).
inline constexpr std::size_t symdiff_polygon_limit = 2000;

// Compares a kernel's output with the reference. When the output carries exact "p/q"
// coordinates (exact kernels), those are compared; otherwise the rounded vertices are
// compared with the reference's vertices rounded to nearest.
Assessment assess(const Output& output, const ExactResult& reference);

// The type of the reference's counterclockwise cycles: island, except where the result
// region lies right of its cycles (hole-type inputs), where counterclockwise cycles are
// holes. Island when the reference has no area cycle.
PolygonType ccw_type_of(const ExactResult& reference);

// Whether the rounded output is valid: is_valid_rounded_output (no crossing or overlapping
// edges, no collapsed ring) and every area ring's exact orientation agrees with its type
// (counterclockwise rings have type `ccw_type`). `why` receives the reason when not.
bool is_valid_output(const Output& output, PolygonType ccw_type, std::string* why = nullptr);

// Whether regions overlap at a vertex where rings meet (turning around it, the region is
// entered twice in a row), or two edges leave a vertex along one ray. Rings must have the
// region on their left when `region_left` (counterclockwise islands), on their right otherwise.
bool have_overlapping_sectors(const Output& output, bool region_left);

// Exact area of the symmetric difference of two results given as area cycles (rings of
// 3+ vertices, nesting decides the region as in the paper's polygon model; unbounded
// results are hole-type). `infinite` when exactly one of them is unbounded; empty when
// RationalKernel rejects the rings (crossing edges).
struct SymmetricDifference {
  bool infinite = false;
  mpq_class area;
  // Whether area(X xor Y) = area(X) + area(Y) - 2 area(X and Y), with area(X), area(Y)
  // from nesting parity computed without the core; empty when not checked (many rings).
  std::optional<bool> consistent;
};
std::optional<SymmetricDifference> symmetric_difference_area(const std::vector<ExactCycle>& x, bool x_unbounded,
                                                   const std::vector<ExactCycle>& y, bool y_unbounded);

// The area of the finite area region of rings by nesting parity, computed without the
// core; empty for more than 64 rings or rings whose edges all lie on another ring.
std::optional<mpq_class> parity_area(const std::vector<std::vector<RationalPoint>>& rings);

// Exact identities RationalKernel must satisfy on island polygons x, y of doubles:
// area(x and x) = parity area of x, and area(x xor y) = area(x) + area(y) - 2 area(x and y).
// Returns a description of the first one violated, or empty (also when not checkable).
std::optional<std::string> violated_identity(const Polygon& x, const Polygon& y);

// Twice the signed area of a ring (shoelace, exact), and the area of a bounded result from
// its typed cycles (islands add, holes subtract; cycles of fewer than 3 vertices add nothing).
mpq_class twice_signed_area(const std::vector<RationalPoint>& ring);
mpq_class typed_area(const std::vector<ExactCycle>& cycles);

// The output's cycles with exact coordinates (parsed "p/q" when present, else the doubles).
std::vector<ExactCycle> exact_cycles(const Output& output);

}  // namespace mk::experiments
