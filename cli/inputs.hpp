// Resolving the command's polygon arguments: a file, `-` for standard input, or inline
// WKT (or JSON) text, read into the paper's polygon model. [MK89 §2.2] [OGC06-103 §7]
// Preconditions: at most one argument of a command is `-` (checked by the caller).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "api/exact_polygon.hpp"
#include "core/polygon.hpp"

namespace mk::cli {

enum class InputSource { standard_input, file, inline_text };

// `-` is standard input; an existing path is a file; otherwise text that looks like WKT
// (a geometry keyword followed by `(`, EMPTY or a Z/M tag) or JSON (starts with `{`) is
// inline text; anything else is taken as a file name so that the error names it.
InputSource classify_input(const std::string& argument);

// One polygon argument, read.
struct Input {
  Polygon polygon;
  std::string name;                     // for messages: "A (file 'x.wkt')", "B (inline WKT)"
  std::vector<std::string> ring_names;  // per ring of `polygon`, as the reader names them
  std::optional<ExactPolygon> exact;    // native JSON with coordinates that are not doubles
};

// Reads and parses one argument; `role` ("A" or "B") starts every error message, which
// then names the source ("file 'x.wkt'", "standard input", "inline WKT") and the reader's
// own position (line, column, polygon, ring, vertex). An empty input is an error (an empty
// polygon is written POLYGON EMPTY). Throws mk::InvalidInput.
Input read_input(const std::string& argument, std::string_view role);

// One argument read as parts, unchecked (io/format.hpp, read_parts_input): for fill rules,
// union-all, intersection-all and make-valid. Errors as for read_input.
struct PartsInput {
  MultiPolygon parts;
  std::string name;
};
PartsInput read_parts(const std::string& argument, std::string_view role);

// The whole of standard input, in binary.
std::string read_standard_input();

}  // namespace mk::cli
