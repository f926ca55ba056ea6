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
// The output form of write_native_json(Output) is read as well: its cycles are the rings
// (those of 3 or more vertices nest by parity into the area part, those of 2 and 1 vertices
// are its dangling edges and isolated points), type hole when "unbounded": the result's
// point set, regular or not (an unbounded result with dangling edges or isolated points is
// refused: a hole-type polygon's degenerate rings would not add their points).
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
