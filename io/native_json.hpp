// The native JSON format: the paper's polygon model (rings plus island/hole type), the only
// format that carries hole-type and degenerate polygons, and the full Boolean output.
// [MK89 §2.2] (polygons, one- and two-sided rings) [MK89 §3.1 step 6] (result types)
// Preconditions: none for the reader (malformed input throws mk::InvalidInput).
#pragma once

#include <string>
#include <string_view>

#include "api/exact_polygon.hpp"
#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk {

// Reads {"type": "island" | "hole", "rings": [[[x, y], ...], ...]}; "type" defaults to
// island. Coordinates are JSON numbers or strings holding an exact rational "p/q" or an
// integer "p" (any size) whose value must be exactly a double. Rings are given without the
// closing vertex (a closing duplicate is removed, as are repeated consecutive vertices); a
// ring of 1 point (one-sided) or 2 points (two-sided) is allowed, an empty ring is not.
// Throws mk::InvalidInput: "native JSON line L, column C: <reason>" for JSON syntax errors,
// "native JSON at <path>: <what>" for content errors (path like "rings[0][3][1]").
// The output form of write_native_json(Output) is read as well: its cycles of 3 or more
// vertices are the rings (nesting by parity gives the result's region), type hole when
// "unbounded"; a result with dangling edges or isolated points is refused.
Polygon read_native_json(std::string_view text);

// The same, with coordinates taken exactly: strings may hold any rational "p/q" or decimal
// "d.ddd[e[+-]n]" (0.1 is 1/10), and the output form's "exact" coordinates are used.
ExactPolygon read_native_json_exact(std::string_view text);

// The input form above, one ring per line; reads back to the same polygon.
std::string write_native_json(const Polygon& polygon);

// A Boolean result: {"kernel", "unbounded", "rounded_valid" (bool or null), "polygons":
// [{"type", "vertices": [[x, y], ...], "exact": [["p/q", "p/q"], ...] (exact kernels
// only)}], "dangling_edges": [[[x, y], [x, y]], ...], "isolated_points": [[x, y], ...]}.
std::string write_native_json(const Output& output, std::string_view kernel);

}  // namespace mk
