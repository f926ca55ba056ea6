// Reading and writing GeoJSON polygonal geometries. [RFC7946 §3] (right-hand rule §3.1.6)
// Preconditions: none for the reader (malformed input throws mk::InvalidInput); the
// writers need finite coordinates and a bounded result.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk {

// Reads a Polygon, MultiPolygon, GeometryCollection (of those, not nested), Feature or
// FeatureCollection; the polygons of all features are listed in one multipolygon (as its
// parts: nothing is merged), and a Feature with a null geometry contributes nothing. Rings must be closed with at least 3
// distinct points; positions have two finite coordinates, or more (an altitude, RFC 7946
// §3.1.1), which are checked and dropped. The result drops the closing vertex and repeated
// consecutive vertices.
// Throws mk::InvalidInput: "GeoJSON line L, column C: <reason>" for JSON syntax errors, and
// "GeoJSON at <path>: <what>" for content errors, where the path looks like
// "features[2].geometry.coordinates[0][3]" ("top level" for the root object).
// With `part_names`, appends each polygon's path ("coordinates", "coordinates[2]",
// "features[1].geometry.coordinates", ...).
MultiPolygon read_geojson(std::string_view text, std::vector<std::string>* part_names = nullptr);

// A Polygon geometry for one polygon, MultiPolygon for several, an empty Polygon for none;
// rings are closed, shells counterclockwise and holes clockwise (right-hand rule).
std::string write_geojson(const MultiPolygon& polygons);

// As above for a Boolean result; dangling edges and isolated points make it a
// GeometryCollection with LineStrings and Points. Throws mk::InvalidInput when the result
// is unbounded.
std::string write_geojson(const Output& output);

}  // namespace mk
