// An SVG picture of a Boolean operation: inputs A and B, the result on top, its dangling
// edges and isolated points, and a legend. [MK89 §2.2] (regions of islands and holes)
// Preconditions: finite coordinates.
#pragma once

#include <string>

#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk {

// A and B are translucent fills with outlines (blue, orange); the result is filled on top
// (green, fill-rule evenodd so holes show) from its irreducible cycles, with the outside
// shaded when it is unbounded or an input is a hole; dangling edges are thick red lines and
// isolated points purple dots. The y axis points up. Coordinates are mapped to pixels here
// rather than by a viewBox transform, because renderers work in single precision and a
// ulp-scale case would collapse to one pixel.
std::string write_svg(const Polygon& a, const Polygon& b, const Output& result);

}  // namespace mk
