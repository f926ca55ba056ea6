// Choosing the input format of a polygon file (WKT, GeoJSON or native JSON) and reading it
// into the paper's polygon model. [OGC06-103 §7] [RFC7946] [MK89 §2.2]
// Preconditions: none; unreadable input throws mk::InvalidInput.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "api/exact_polygon.hpp"
#include "core/polygon.hpp"

namespace mk {

enum class Format { wkt, geojson, native_json };

// "WKT", "GeoJSON", "native JSON": the names used in messages.
std::string_view format_name(Format format);

// By the file name's extension when it has one of .wkt, .geojson or .json (any case); a
// .json file whose top-level object has a "rings" member (or "polygons": a result) is native JSON, any other
// GeoJSON. Without a known extension, by the content: text starting with '{' is JSON as
// above, anything else WKT. The content scan stops early and copies nothing.
Format sniff_format(std::string_view text, std::string_view filename_hint);

// A polygon read from text, with the names its rings have in messages.
struct PolygonInput {
  Polygon polygon;
  Format format = Format::wkt;
  // Per ring of `polygon`: "polygon 1, ring 0" (WKT), "coordinates[1][0]" (GeoJSON),
  // "rings[3]" (native JSON).
  std::vector<std::string> ring_names;
  // Native JSON with a coordinate that is not a double: the polygon exactly (`polygon` then
  // holds its nearest doubles).
  std::optional<ExactPolygon> exact;
};

// Reads a polygon in the sniffed format. WKT and GeoJSON give one island-type polygon whose
// rings are the shells and holes, once checked that reading them by nesting [MK89 §2.2]
// gives what OGC means (io/parts.hpp: the union of the parts, each its shell less its holes).
PolygonInput read_polygon_input(std::string_view text, std::string_view filename_hint);

// The parts of a WKT or GeoJSON input, not checked against each other or themselves: what
// fill rules, union-all, intersection-all and make-valid read (any rings: crossing,
// overlapping, repeating vertices). A WKT text of two or more lines each of which starts a
// geometry (a keyword, then `(` or EMPTY) is read as one geometry per line, its parts in
// line order; errors then start with "line L: ". Native JSON, which has no parts, is refused.
MultiPolygon read_parts_input(std::string_view text, std::string_view filename_hint);

// The polygon alone.
Polygon read_polygon(std::string_view text, std::string_view filename_hint);

}  // namespace mk
