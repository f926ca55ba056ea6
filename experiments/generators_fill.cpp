// Generators of self-crossing and multi-part input for the fill rules (issue 13):
// self_crossing_random, bowtie_degenerate, pentagram, traced_twice, overlapping_multipart.
// Each builds A and B on the integer lattice (shared vertices, collinear overlaps and
// vertices on edges happen by construction), then applies a lattice symmetry and translation
// (variant `lattice`, exact) or a rotation by a random angle rounded to doubles (variant
// `rotated`: crossings no longer on the lattice, collinearity broken). The case's fill rule
// is its parameter `rule` (fill_rule_of); for `union` the parts are oriented here as the
// library does for an OGC multipolygon (mk::fill_rule_polygon), since the kernels read the
// rings of a Polygon as nonzero under that rule.
// [BRIEF §1, extended by issue 13] (an input's region under a fill rule)
// Preconditions: the `grid` parameter, when given, is at least 4.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "api/mkbool.hpp"
#include "experiments/generator_util.hpp"
#include "experiments/generators.hpp"

namespace mk::experiments {

using detail::LatticePart;
using detail::LatticeParts;
using detail::variant_index;

namespace {

IRing random_ring(std::mt19937_64& rng, std::int64_t grid, int n) {
  IRing r;
  for (int i = 0; i < n; ++i) r.push_back({uniform(rng, 0, grid), uniform(rng, 0, grid)});
  return r;
}

IRing rectangle(std::mt19937_64& rng, std::int64_t grid) {
  const std::int64_t x0 = uniform(rng, 0, grid - 1), y0 = uniform(rng, 0, grid - 1);
  return detail::box(x0, y0, uniform(rng, x0 + 1, grid), uniform(rng, y0 + 1, grid));
}

// Crossing at the lattice point (x + s, y + s), where other bow-ties' vertices may lie.
IRing bowtie(std::mt19937_64& rng, std::int64_t grid) {
  const std::int64_t s = uniform(rng, 1, 2);
  const std::int64_t x = uniform(rng, 0, grid - 2 * s), y = uniform(rng, 0, grid - 2 * s);
  return {{x, y}, {x + 2 * s, y + 2 * s}, {x + 2 * s, y}, {x, y + 2 * s}};
}

// Star polygons on lattice points: {5/2} and two 7-point stars (centres wound 2 or 3 times).
IRing star_polygon(std::mt19937_64& rng) {
  static const std::array<std::vector<IPoint>, 3> stars{{
      {{4, 0}, {6, 6}, {8, 0}, {3, 4}, {9, 4}},
      {{5, 0}, {2, 7}, {8, 6}, {1, 2}, {9, 2}, {2, 6}, {8, 7}},
      {{4, 0}, {8, 5}, {1, 7}, {2, 1}, {8, 2}, {3, 8}, {0, 4}},
  }};
  const IPoint d{uniform(rng, -2, 2), uniform(rng, -2, 2)};
  return translated(stars[static_cast<std::size_t>(uniform(rng, 0, 2))], d);
}

LatticeParts make_parts(std::string_view generator, std::mt19937_64& rng, std::int64_t grid) {
  LatticeParts parts;
  const auto part = [&](IRing shell) -> LatticePart& { return parts.emplace_back(LatticePart{std::move(shell), {}}); };
  if (generator == "self_crossing_random") {
    for (std::int64_t k = uniform(rng, 1, 2); k > 0; --k) part(random_ring(rng, grid, static_cast<int>(uniform(rng, 4, 9))));
    if (uniform(rng, 0, 2) == 0) parts[0].holes.push_back(random_ring(rng, grid, static_cast<int>(uniform(rng, 3, 5))));
  } else if (generator == "bowtie_degenerate") {
    for (std::int64_t k = uniform(rng, 1, 3); k > 0; --k) part(bowtie(rng, grid));
  } else if (generator == "pentagram") {
    part(star_polygon(rng));
    if (uniform(rng, 0, 2) == 0) part(rectangle(rng, grid));
  } else if (generator == "traced_twice") {  // winding 2, or 3 or 1 with the ring again
    const IRing r = uniform(rng, 0, 1) == 0 ? rectangle(rng, grid) : random_ring(rng, grid, 4);
    IRing twice = r;
    twice.insert(twice.end(), r.begin(), r.end());
    part(twice);
    if (uniform(rng, 0, 1) == 0) part(uniform(rng, 0, 1) == 0 ? r : reversed(r));
  } else {  // overlapping_multipart: shells sharing edges and vertices, some with holes
    for (std::int64_t k = uniform(rng, 2, 5); k > 0; --k) {
      LatticePart& p = part(uniform(rng, 0, 2) == 0 ? random_ring(rng, grid, 3) : rectangle(rng, grid));
      if (uniform(rng, 0, 2) == 0) p.holes.push_back(rectangle(rng, grid));
    }
  }
  return parts;
}

PolygonPair fill_pair(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"lattice", "rotated"});
  const FillRule rule = *fill_rule_of(spec);
  const std::int64_t grid = spec.param("grid", 8);
  if (grid < 4) throw std::invalid_argument("generator " + spec.generator + ": grid must be at least 4");
  const LatticeParts a = make_parts(spec.generator, rng, grid), b = make_parts(spec.generator, rng, grid);
  const LatticeMap map = random_lattice_map(rng, 40);
  MultiPolygon ma = detail::to_multipolygon(rng, a, map), mb = detail::to_multipolygon(rng, b, map);
  if (v == 1) {
    const double angle = 6.283185307179586 * uniform01(rng);
    detail::rotate(ma, angle);
    detail::rotate(mb, angle);
  }
  return {fill_rule_polygon(ma, rule), fill_rule_polygon(mb, rule)};
}

}  // namespace

PolygonPair self_crossing_random(const CaseSpec& spec) { return fill_pair(spec); }
PolygonPair bowtie_degenerate(const CaseSpec& spec) { return fill_pair(spec); }
PolygonPair pentagram(const CaseSpec& spec) { return fill_pair(spec); }
PolygonPair traced_twice(const CaseSpec& spec) { return fill_pair(spec); }
PolygonPair overlapping_multipart(const CaseSpec& spec) { return fill_pair(spec); }

bool is_fill_generator(std::string_view name) {
  return name == "self_crossing_random" || name == "bowtie_degenerate" || name == "pentagram" ||
         name == "traced_twice" || name == "overlapping_multipart";
}

std::optional<FillRule> fill_rule_of(const CaseSpec& spec) {
  const bool set = is_set_generator(spec.generator);
  if (!set && !is_fill_generator(spec.generator)) return std::nullopt;
  constexpr FillRule rules[] = {FillRule::evenodd, FillRule::nonzero, FillRule::positive, FillRule::negative,
                                FillRule::union_};
  const std::int64_t r = spec.param("rule", set ? 4 : 0);
  if (r < 0 || r > 4) {
    throw std::invalid_argument("generator " + spec.generator + ": rule must be 0-4 (evenodd, nonzero, positive, negative, union)");
  }
  return rules[r];
}

}  // namespace mk::experiments
