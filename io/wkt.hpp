// Reading and writing OGC Well-Known Text for polygonal geometries.
// [OGC06-103 §7] (WKT grammar) [OGC06-103 §6.1.11] (polygon rings)
// Preconditions: none for the reader (every malformed text throws mk::InvalidInput);
// the writers need finite coordinates and a bounded result.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk {

// Reads POLYGON, MULTIPOLYGON or a GEOMETRYCOLLECTION of those (collections do not nest),
// each possibly EMPTY; keywords are case-insensitive. Z, M and ZM geometries (tagged,
// "POLYGON Z", or with 3 or 4 numbers per vertex) are read with those coordinates checked
// and dropped; every vertex of one text has the same number of coordinates. Rings must be
// closed and have at least 3 distinct points; the result drops the closing vertex and
// repeated consecutive vertices. Linear time, no recursion on the input's size.
// Throws mk::InvalidInput "WKT line L, column C[ (polygon P, ring R, vertex V)]: what",
// with 1-based line and column and 0-based polygon (in text order), ring (0 = shell) and
// vertex (in text order) indices. With `part_names`, appends "polygon P" for each polygon
// returned (P counts EMPTY polygons too, as the messages do).
MultiPolygon read_wkt(std::string_view text, std::vector<std::string>* part_names = nullptr);

// POLYGON for one polygon, MULTIPOLYGON for several, POLYGON EMPTY for none; rings are
// closed, shells counterclockwise, holes clockwise, coordinates in shortest round-trip form.
// `threads` (0: every core) format a large output in parts, joined into the same text.
std::string write_wkt(const MultiPolygon& polygons, unsigned threads = 1);

// As above for a Boolean result; dangling edges and isolated points turn it into a
// GEOMETRYCOLLECTION of the (multi)polygon, LINESTRINGs and POINTs. Throws
// mk::InvalidInput for an unbounded result, which WKT cannot express.
std::string write_wkt(const Output& output, unsigned threads = 1);

}  // namespace mk
