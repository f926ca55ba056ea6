// Failure artefacts of a sweep: every failure of an exact kernel as a ready regression case
// file (tests/regression/cases/<generator>_<seed>.wkt format), and SVG pictures (A, B, the
// exact result, the kernel's result) of the smallest failing cases of each kernel; and
// pictures of results that certified rounding snapped (snapping_pictures.hpp).
// [MK89 §3.3] (exact kernels never fail: each failure is a bug to keep as a test) [Ho99]
// Preconditions: rows come from run_sweep over the same generators; the out directory is
// writable.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "api/mkbool.hpp"
#include "core/fill_rule.hpp"
#include "core/output.hpp"
#include "core/polygon.hpp"
#include "experiments/case.hpp"
#include "experiments/pictures.hpp"
#include "experiments/results.hpp"

namespace mk::experiments {

// The regression case format, four lines, an optional fifth and '#' comment lines:
//   A as WKT (POLYGON / MULTIPOLYGON) when it is island-type with rings of 3+ points in
//     shell-then-holes order and no fill rule, else as native JSON on one line (rings in
//     their given directions, as a fill rule reads them)
//   B the same way
//   the operation: intersection | union | difference | xor
//   regular | nonregular
//   fill_rule evenodd | nonzero | positive | negative | union   (only when the case has one)
// A set case (Case::parts) writes line 1 as the parts, a MULTIPOLYGON with every ring as
// given (direction, start), line 2 as MULTIPOLYGON EMPTY, and line 3 union_all or
// intersection_all.
std::string regression_case_text(const Polygon& a, const Polygon& b, Operation op, bool regular,
                                 const std::vector<std::string>& comments,
                                 std::optional<FillRule> fill_rule = std::nullopt);
std::string regression_case_text(const Case& c, Operation op, bool regular, const std::vector<std::string>& comments);

struct RegressionCase {
  Polygon a;
  Polygon b;
  Operation op = Operation::intersection;
  bool regular = true;
  std::optional<FillRule> fill_rule;
  std::optional<MultiPolygon> parts;  // a set case: op is union (union_all) or intersection
};
// Reads the format above (WKT or native JSON per line); throws mk::InvalidInput.
RegressionCase read_regression_case(const std::string& text);

// The case's run with options.kernel and options.regular (options.op, fill_rule and the
// operands from the case): compute, union_all or intersection_all.
BooleanOutput replay_regression_case(const RegressionCase& c, BooleanOptions options);


struct Artefact {
  // regression_case: a case file; picture: a failure picture; snapping: a result rounded to
  // the nearest doubles beside its certified (snap-rounded) output.
  enum class Kind { regression_case, picture, snapping } kind = Kind::picture;
  std::string path;  // relative to the output directory
  ResultRow row;     // the run it shows
};

// The kind's name in artefacts.csv ("regression_case", "picture", "snapping"), and back
// (empty for an unknown name).
std::string_view artefact_kind_name(Artefact::Kind kind);
std::optional<Artefact::Kind> parse_artefact_kind(std::string_view name);

struct ArtefactOptions {
  std::size_t pictures_per_group = 3;  // per (kernel, generator), smallest cases first
  double timeout_seconds = 60;         // per artefact, in a forked child
  std::size_t snapping_per_generator = 3;  // snapped results of kernel `exact` per generator
};

// Picks the failures and the snapped results, regenerates their cases and writes
// DIR/regression/*.wkt, DIR/pictures/<kernel>/*.svg and DIR/pictures/snapping/*.svg;
// returns what it wrote (also listed in DIR/artefacts.csv).
std::vector<Artefact> write_artefacts(const std::vector<ResultRow>& rows, const std::string& dir,
                                      const ArtefactOptions& options);

// Reads DIR/artefacts.csv back (for `report`); empty when absent.
std::vector<Artefact> read_artefacts(const std::string& dir);

Operation parse_operation(const std::string& name);  // throws std::invalid_argument

}  // namespace mk::experiments
