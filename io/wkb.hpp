// Reading and writing OGC Well-Known Binary for polygonal geometries (what shapely and
// GEOS hand over without loss). [OGC06-103 §8] (WKB encoding) [OGC06-103 §6.1.11] (rings)
// Preconditions: none for the reader (every malformed byte string throws mk::InvalidInput);
// the writers need finite coordinates and a bounded result.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk {

// Reads a Polygon (type 3), MultiPolygon (6) or a GeometryCollection (7) of those
// (collections do not nest), in either byte order, each part with its own byte order as
// WKB allows. Also takes PostGIS's extended form with an SRID (flag 0x20000000; the SRID
// is skipped). Z and M coordinates (ISO types 1003..3007, or the extended flags) are checked
// and dropped as read_wkt does, every geometry of one input having the same number of
// coordinates per vertex; other geometry types are refused. Rings must be closed with at least 3 distinct
// points; the result drops the closing vertex and repeated consecutive vertices. An empty
// hole ring is skipped, an empty shell ring refused (an empty polygon has no rings).
// Counts are checked against the bytes left before anything is allocated.
// Throws mk::InvalidInput "WKB byte B[ (polygon P, ring R, vertex V)]: what", with B the
// 0-based offset of the offending field and the indices as in read_wkt. With `part_names`,
// appends "polygon P" for each polygon returned, as read_wkt does.
MultiPolygon read_wkb(std::string_view bytes, std::vector<std::string>* part_names = nullptr);

// Little-endian WKB: Polygon for one polygon, MultiPolygon for several, an empty Polygon
// (no rings) for none; rings closed, shells counterclockwise, holes clockwise.
std::string write_wkb(const MultiPolygon& polygons);

// As above for a Boolean result; dangling edges and isolated points make it a
// GeometryCollection with LineStrings and Points. Throws mk::InvalidInput for an unbounded
// result, which WKB cannot express.
std::string write_wkb(const Output& output);

}  // namespace mk
