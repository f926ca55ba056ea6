// OGC polygons-with-holes for the peer libraries: the OGC form of a polygon of the paper's
// model (rings nest by parity: even depth a shell, odd depth a hole of the ring around it),
// and an exact OGC-style validity check of polygons of doubles that peers return.
// [MK89 §2.2] (inclusion forest) [OGC06-103 §6.1.11] (polygon validity)
// Preconditions: none; coordinates are compared exactly (GMP rationals).
#pragma once

#include <optional>
#include <string>

#include "core/polygon.hpp"

namespace mk::experiments {

// Shells (rings at even nesting depth) each with the holes directly inside it, in ring
// order. Empty for a hole-type polygon, a ring of fewer than 3 points, or a ring whose
// nesting cannot be decided (every vertex on another ring).
std::optional<MultiPolygon> ogc_form(const Polygon& p);

// Every ring with the vertices of all the rings that lie inside its edges inserted, in
// order along the edge: rings that touch at points then share vertices.
std::vector<Ring> vertex_complete(const std::vector<Ring>& rings);

// Whether polygons of doubles are valid in the OGC sense, decided exactly: finite
// coordinates; rings of 3+ distinct points and non-zero area; after inserting every vertex
// that lies inside an edge (touching is allowed at points), no two edges cross or overlap
// and no two regions overlap where rings meet; every hole inside its own shell and every
// shell outside the other shells' regions. `why` receives the first reason found.
bool is_valid_ogc_exact(const MultiPolygon& polygons, std::string* why = nullptr);

}  // namespace mk::experiments
