// Generators of sets of polygons for the N-ary operations union_all and intersection_all
// (issue 13): random_set, coverage_grid, nested_parts. Each builds its parts on the integer
// lattice, where parts share edges and vertices and overlap exactly, then applies a lattice
// symmetry and translation (variant `lattice`) or also a rotation by a random angle rounded
// to doubles (variant `rotated`), each ring reversed or not and started anywhere, as
// generators_fill.cpp does. Parts are valid OGC polygons on their own; the set is not.
// [BRIEF §1, extended by issue 13] (union_all: the union of the parts; intersection_all)
// Preconditions: the parameter n, when given, is at least 1 (at most 1000 for random_set,
// 40 for coverage_grid, 50 for nested_parts: the lattice helpers' coordinates stay small).
#include <stdexcept>

#include "experiments/generator_util.hpp"
#include "experiments/generators.hpp"

namespace mk::experiments {

using detail::box;
using detail::LatticePart;
using detail::LatticeParts;

namespace {

std::int64_t size_param(const CaseSpec& spec, std::int64_t fallback, std::int64_t most) {
  const std::int64_t n = spec.param("n", fallback);
  if (n < 1 || n > most) {
    throw std::invalid_argument("generator " + spec.generator + ": n must be 1 to " + std::to_string(most));
  }
  return n;
}

// The parts, varied by one lattice map (and rotated for variant `rotated`).
MultiPolygon finish_set(const CaseSpec& spec, std::mt19937_64& rng, const LatticeParts& parts) {
  const std::size_t v = detail::variant_index(spec, {"lattice", "rotated"});
  MultiPolygon mp = detail::to_multipolygon(rng, parts, random_lattice_map(rng, 40));
  if (v == 1) detail::rotate(mp, 6.283185307179586 * uniform01(rng));
  return mp;
}

// A triangle of nonzero area with vertices in [0, grid]^2.
IRing random_triangle(std::mt19937_64& rng, std::int64_t grid) {
  for (;;) {
    IRing t;
    for (int i = 0; i < 3; ++i) t.push_back({uniform(rng, 0, grid), uniform(rng, 0, grid)});
    if (twice_area(t) != 0) return t;
  }
}

}  // namespace

// n parts on a grid about 2 sqrt(n) wide, so that they overlap several deep: rectangles,
// triangles and convex polygons, a fifth of the rectangles and convex ones with a hole, and
// a tenth of the parts repeating an earlier one exactly (identical parts, both directions).
// In half of the cases every part is a rectangle around the grid's centre, so that
// intersection_all has something to find.
MultiPolygon random_set(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::int64_t n = size_param(spec, 32, 1000);
  std::int64_t grid = 6;
  while (grid * grid < 4 * n) ++grid;
  const bool around_centre = uniform(rng, 0, 1) == 0;
  const std::int64_t c = grid / 2;
  LatticeParts parts;
  for (std::int64_t i = 0; i < n; ++i) {
    if (!parts.empty() && uniform(rng, 0, 9) == 0) {
      parts.push_back(parts[static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(parts.size()) - 1))]);
      continue;
    }
    const std::int64_t kind = around_centre ? 0 : uniform(rng, 0, 4);
    LatticePart p;
    if (kind <= 2) {  // a rectangle, around the centre or anywhere
      const std::int64_t x0 = around_centre ? uniform(rng, 0, c - 1) : uniform(rng, 0, grid - 1);
      const std::int64_t y0 = around_centre ? uniform(rng, 0, c - 1) : uniform(rng, 0, grid - 1);
      const std::int64_t x1 = around_centre ? uniform(rng, c + 1, grid) : uniform(rng, x0 + 1, grid);
      const std::int64_t y1 = around_centre ? uniform(rng, c + 1, grid) : uniform(rng, y0 + 1, grid);
      p.shell = box(x0, y0, x1, y1);
      if (x1 - x0 >= 3 && y1 - y0 >= 3 && uniform(rng, 0, 4) == 0) {
        const std::int64_t hx = uniform(rng, x0 + 1, x1 - 2), hy = uniform(rng, y0 + 1, y1 - 2);
        p.holes.push_back(box(hx, hy, uniform(rng, hx + 1, x1 - 1), uniform(rng, hy + 1, y1 - 1)));
      }
    } else if (kind == 3) {
      p.shell = random_triangle(rng, grid);
    } else {
      const IPoint centre{uniform(rng, 2, grid - 2), uniform(rng, 2, grid - 2)};
      p.shell = random_convex(rng, centre, 2 + uniform(rng, 0, 2), static_cast<int>(uniform(rng, 4, 8)));
      if (uniform(rng, 0, 4) == 0) {
        IRing h = detail::hole_inside(rng, p.shell, centre, 1);
        if (!h.empty()) p.holes.push_back(std::move(h));
      }
    }
    parts.push_back(std::move(p));
  }
  return finish_set(spec, rng, parts);
}

// The coverage case: an n x n grid of unit squares, each edge shared by two parts (in
// opposite directions when both are counterclockwise). A cell is missing with probability
// 1/8, split into two triangles along a diagonal with 1/8, or merged with its right-hand
// neighbour into a 2 x 1 rectangle with 1/8 (its long edges then meet the squares above and
// below at a vertex in their middle: vertex_on_edge).
MultiPolygon coverage_grid(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::int64_t n = size_param(spec, 8, 40);
  LatticeParts parts;
  for (std::int64_t y = 0; y < n; ++y) {
    for (std::int64_t x = 0; x < n; ++x) {
      const std::int64_t pick = uniform(rng, 0, 7);
      if (pick == 0) continue;
      if (pick == 1) {
        parts.push_back({{{x, y}, {x + 1, y}, {x + 1, y + 1}}, {}});
        parts.push_back({{{x, y}, {x + 1, y + 1}, {x, y + 1}}, {}});
      } else if (pick == 2 && x + 1 < n) {
        parts.push_back({box(x, y, x + 2, y + 1), {}});
        ++x;
      } else {
        parts.push_back({box(x, y, x + 1, y + 1), {}});
      }
    }
  }
  if (parts.empty()) parts.push_back({box(0, 0, 1, 1), {}});
  return finish_set(spec, rng, parts);
}

// n nests near each other (they overlap): a square with a square hole, and in the hole a
// part that fills it exactly, lies strictly inside it, touches it along an edge, or has a
// hole of its own with a part inside that; and a quarter of the nests covered by a part
// around the whole nest.
MultiPolygon nested_parts(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::int64_t n = size_param(spec, 3, 50);
  const std::int64_t spread = 4 + 2 * n;
  LatticeParts parts;
  for (std::int64_t k = 0; k < n; ++k) {
    const std::int64_t x = uniform(rng, 0, spread), y = uniform(rng, 0, spread);
    const std::int64_t side = uniform(rng, 7, 11), inset = uniform(rng, 1, 2);
    const std::int64_t hx0 = x + inset, hy0 = y + inset, hx1 = x + side - inset, hy1 = y + side - inset;
    parts.push_back({box(x, y, x + side, y + side), {box(hx0, hy0, hx1, hy1)}});
    switch (uniform(rng, 0, 3)) {
      case 0: parts.push_back({box(hx0, hy0, hx1, hy1), {}}); break;  // fills the hole exactly
      case 1: parts.push_back({box(hx0 + 1, hy0 + 1, hx1 - 1, hy1 - 1), {}}); break;
      case 2: parts.push_back({box(hx0, hy0 + 1, hx1 - 1, hy1 - 1), {}}); break;  // touches along an edge
      default:
        if (hx1 - hx0 >= 5) {
          parts.push_back({box(hx0 + 1, hy0 + 1, hx1 - 1, hy1 - 1), {box(hx0 + 2, hy0 + 2, hx1 - 2, hy1 - 2)}});
          parts.push_back({box(hx0 + 2, hy0 + 2, hx1 - 2, hy1 - 2), {}});
        } else {
          parts.push_back({box(hx0 + 1, hy0 + 1, hx1 - 1, hy1 - 1), {}});
        }
    }
    if (uniform(rng, 0, 3) == 0) parts.push_back({box(x - 1, y - 1, x + side + 1, y + side + 1), {}});
  }
  return finish_set(spec, rng, parts);
}

bool is_set_generator(std::string_view name) {
  return name == "random_set" || name == "coverage_grid" || name == "nested_parts";
}

}  // namespace mk::experiments
