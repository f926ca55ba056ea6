// Helpers shared by the generator files: variant lookup, and the final exact variation of a
// lattice configuration (symmetry, translation, ring direction, start vertex).
// [MK89 §3.1 step 1] (orientations are normalised, so input directions may vary)
// Preconditions: rings are lattice rings small enough for lattice.hpp.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "experiments/case.hpp"
#include "experiments/lattice.hpp"

namespace mk::experiments::detail {

// Index of spec.variant in the list, or std::invalid_argument naming the generator.
inline std::size_t variant_index(const CaseSpec& spec, std::initializer_list<std::string_view> variants) {
  std::size_t i = 0;
  for (const auto v : variants) {
    if (spec.variant == v) return i;
    ++i;
  }
  throw std::invalid_argument("generator " + spec.generator + ": unknown variant '" + spec.variant + "'");
}

struct LatticePair {
  std::vector<IRing> a;
  std::vector<IRing> b;
  PolygonType a_type = PolygonType::island;
  PolygonType b_type = PolygonType::island;
};

// Applies one random lattice symmetry and translation to both polygons (the degeneracy
// survives exactly), reverses all rings or none (step 1 must normalise either), and starts
// each ring at a random vertex unless `keep_start` (the identical generator's variants).
inline PolygonPair finish(std::mt19937_64& rng, const LatticePair& p, bool keep_start = false) {
  const LatticeMap map = random_lattice_map(rng, 40);
  const bool reverse_all = uniform(rng, 0, 1) == 1;
  const auto convert = [&](const std::vector<IRing>& rings, PolygonType type) {
    Polygon out;
    out.type = type;
    for (const auto& r : rings) {
      IRing m = apply(map, r);
      if (reverse_all) m = reversed(m);
      if (!keep_start) m = shifted_start(m, static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(m.size()) - 1)));
      out.rings.push_back(to_ring(m));
    }
    return out;
  };
  PolygonPair out;
  out.a = convert(p.a, p.a_type);
  out.b = convert(p.b, p.b_type);
  return out;
}

inline IRing box(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A convex hole strictly inside `outer`, or empty after a few failed tries.
inline IRing hole_inside(std::mt19937_64& rng, const IRing& outer, IPoint centre, std::int64_t radius) {
  for (int tries = 0; tries < 50; ++tries) {
    IRing h = random_convex(rng, centre, radius, static_cast<int>(uniform(rng, 3, 6)));
    if (is_strictly_inside(outer, h)) return h;
  }
  return {};
}

// Parts on the lattice for the fill-rule and set generators: a shell and its holes each.
struct LatticePart {
  IRing shell;
  std::vector<IRing> holes;
};
using LatticeParts = std::vector<LatticePart>;

// Each ring reversed or not and started anywhere; the map applied; then doubles.
inline MultiPolygon to_multipolygon(std::mt19937_64& rng, const LatticeParts& parts, const LatticeMap& map) {
  const auto ring = [&](const IRing& r) {
    IRing m = apply(map, r);
    if (uniform(rng, 0, 1) == 1) m = reversed(m);
    return to_ring(shifted_start(m, static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(m.size()) - 1))));
  };
  MultiPolygon mp;
  for (const LatticePart& p : parts) {
    OgcPolygon& o = mp.emplace_back();
    o.shell = ring(p.shell);
    for (const IRing& h : p.holes) o.holes.push_back(ring(h));
  }
  return mp;
}

// A rotation by a random angle about the origin, rounded to doubles: shared points stay
// shared, but crossings leave the lattice and collinear edges mostly stop being collinear.
inline void rotate(MultiPolygon& mp, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const auto turn = [&](Ring& r) {
    for (Point& p : r) p = {c * p.x - s * p.y, s * p.x + c * p.y};
  };
  for (OgcPolygon& p : mp) {
    turn(p.shell);
    for (Ring& h : p.holes) turn(h);
  }
}

}  // namespace mk::experiments::detail
