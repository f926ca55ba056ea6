// Random test polygons on small integer grids (dense coincidences: shared vertices,
// collinear edges, vertices on edges), shared by the core test suites.
#pragma once

#include "oracle.hpp"

namespace mk::test {

// A star, sometimes with a star hole strictly inside and a second component strictly apart,
// sometimes of hole type. Regular by construction.
inline Polygon random_polygon(std::mt19937_64& rng, bool allow_hole_type) {
  std::uniform_int_distribution<int> coin(0, 3);
  std::uniform_int_distribution<int> centre(1, 5);
  std::uniform_int_distribution<int> count(3, 8);
  Polygon p;
  const double cx = centre(rng);
  const double cy = centre(rng);
  p.rings.push_back(random_star(rng, cx, cy, 2, 4, count(rng)));
  if (p.rings[0].empty()) return random_polygon(rng, allow_hole_type);
  const auto all_vertices = [](const Ring& r, const Ring& other, Location want) {
    const auto q = to_qrings(Polygon{{other}, PolygonType::island});
    for (const auto& v : r) {
      if (locate(q, PolygonType::island, qp(v.x, v.y)) != want) return false;
    }
    return true;
  };
  if (coin(rng) == 0) {
    Ring hole = random_star(rng, cx, cy, 1, 1, count(rng));
    if (hole.size() >= 3 && all_vertices(hole, p.rings[0], Location::inside) &&
        all_vertices(p.rings[0], hole, Location::outside)) {
      p.rings.push_back(hole);
    }
  }
  if (coin(rng) == 0) {
    Ring other = random_star(rng, cx + 5, cy + centre(rng) - 3, 1, 2, count(rng));
    if (other.size() >= 3 && all_vertices(other, p.rings[0], Location::outside) &&
        all_vertices(p.rings[0], other, Location::outside)) {
      p.rings.push_back(other);
    }
  }
  if (allow_hole_type && coin(rng) == 0) p.type = PolygonType::hole;
  return p;
}

inline std::string describe(const Polygon& p) {
  std::string s = p.type == PolygonType::island ? "island[" : "hole[";
  for (const auto& r : p.rings) {
    s += "(";
    for (const auto& v : r) s += std::to_string(v.x) + " " + std::to_string(v.y) + ", ";
    s += ")";
  }
  return s + "]";
}

}  // namespace mk::test
