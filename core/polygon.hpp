// The polygon model of the paper: rings plus an island/hole type; operations and result types.
// [MK89 §2.2] [MK89 §2.3]
// Preconditions: none; validation of coordinates happens in validate_polygon (core/error.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "kernel/point.hpp"

namespace mk {

// [MK89 §2.2] An island's region is FAR(P) plus its boundary; a hole's region is the
// closure of the complement of FAR(P).
enum class PolygonType : std::uint8_t { island, hole };

// A closed ring given without its closing vertex (the last vertex connects to the first).
// One vertex is a one-sided polygon (a point), two distinct vertices a two-sided one.
template <class P>
using BasicRing = std::vector<P>;

template <class P>
struct BasicPolygon {
  std::vector<BasicRing<P>> rings;
  PolygonType type = PolygonType::island;
};

using Ring = BasicRing<Point>;

// Drops a ring's repeated points: each point equal to the one before it, and at the end
// those equal to the first (the ring is read closed). The readers (io/ring_rules.hpp) and the
// written output (core/to_output.hpp) drop them alike.
inline void remove_repeated_points(Ring& ring) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (kept == 0 || !(ring[i] == ring[kept - 1])) ring[kept++] = ring[i];
  }
  while (kept > 1 && ring[kept - 1] == ring[0]) --kept;
  ring.resize(kept);
}
using Polygon = BasicPolygon<Point>;

// An OGC polygon with holes: a shell and the holes directly inside it. Used by the
// readers and writers of WKT and GeoJSON and by the output assembly [MK89 §2.2, forest].
struct OgcPolygon {
  Ring shell;
  std::vector<Ring> holes;
};
using MultiPolygon = std::vector<OgcPolygon>;

// [MK89 §2.3] plus symmetric difference, which the paper does not have.
enum class Operation : std::uint8_t { intersection, union_, difference, symmetric_difference };

constexpr std::string_view operation_name(Operation op) {
  switch (op) {
    case Operation::intersection: return "intersection";
    case Operation::union_: return "union";
    case Operation::difference: return "difference";
    case Operation::symmetric_difference: return "xor";
  }
  return "?";
}

constexpr PolygonType opposite(PolygonType t) {
  return t == PolygonType::island ? PolygonType::hole : PolygonType::island;
}

// Converts an OGC multipolygon into the paper's model: one island-type polygon whose rings
// are all shells and holes (their nesting, not their direction, decides what they are).
inline Polygon to_polygon(const MultiPolygon& mp) {
  Polygon p;
  for (const auto& part : mp) {
    p.rings.push_back(part.shell);
    for (const auto& h : part.holes) p.rings.push_back(h);
  }
  return p;
}

}  // namespace mk
