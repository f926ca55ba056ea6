// Multi-part OGC input read into the paper's model without reinterpreting it: the parts of a
// MULTIPOLYGON (or of a GeoJSON FeatureCollection) mean their union, each part its shell less
// its holes; the paper reads rings by their nesting (even-odd). The two readings agree exactly
// when, with shells counterclockwise and holes clockwise, every point is wound around 0 or 1
// times, by each part alone and by all parts together; anything else is refused by name.
// [OGC06-103 §6.1.11] (polygon and multipolygon rules) [MK89 §2.2] (regions from nesting)
// Preconditions: the rings have passed the readers' ring rules (closed, 3+ distinct points).
#pragma once

#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/polygon.hpp"

namespace mk {

// How messages name the parts and rings of one input.
struct PartNames {
  std::vector<std::string> parts;  // per part: "polygon 2" (WKT), "features[1].geometry.coordinates" (GeoJSON)
  bool json_paths = false;         // rings are "<part>[k]" (GeoJSON) rather than "<part>, ring k" (WKT)
};

// The name of ring k (0: the shell) of part `part`.
std::string ring_name(const PartNames& names, std::size_t part, std::size_t k);

// Crossing edges of `polygon` in plain words: both edges by their end points and the rings
// they belong to, named by `ring_names` (one per ring of `polygon`).
std::string describe_crossing(const CrossingEdges& e, const Polygon& polygon, const std::vector<std::string>& ring_names);

// The rings of `mp`, part after part, shell first, as one island-type polygon (what
// core/polygon.hpp's to_polygon gives), once checked. Throws mk::InvalidInput naming the parts
// or rings and what is wrong: a part inside (or overlapping, or repeating) another, a hole not
// inside its shell, holes inside (or overlapping) each other, a ring covering an area twice or
// running the wrong way around part of it, or crossing edges (with their end points). Parts
// that only touch, at points or along edges (a coverage), are accepted: their union is what
// the paper's reading gives too. Exact, and O(n log n) but for the point queries step 1 makes.
Polygon to_checked_polygon(const MultiPolygon& mp, const PartNames& names);

}  // namespace mk
