// paper_figures: analogues of the example figures 6-12 of the paper's Appendix A, each on
// the lattice and varied by an exact scale, symmetry and translation from the seed.
// [MK89 Appendix A] (Fig. 6 two stars; Fig. 7 same vertex set; Fig. 8 three irreducible
// parts with vertices on edges; Fig. 9 three holes with collinear edges; Fig. 10 collinear
// overlapping edges and a single-point result; Figs. 11-12 regular != non-regular)
// Preconditions: none. The figures themselves are lost from our copy of the text; these
// follow the captions.
#include <cmath>

#include "experiments/generator_util.hpp"
#include "experiments/generators.hpp"

namespace mk::experiments {

using detail::box;
using detail::finish;
using detail::LatticePair;
using detail::variant_index;

namespace {

bool is_simple(const IRing& r) {
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) {
        // Adjacent edges share one endpoint; they must not fold back over each other.
        const IPoint shared = j == i + 1 ? r[j] : r[i];
        const IPoint u = j == i + 1 ? r[i] : r[(i + 1) % n];
        const IPoint w = j == i + 1 ? r[(j + 1) % n] : r[n - 2];
        if (orient(shared, u, w) == 0 && (u.x - shared.x) * (w.x - shared.x) + (u.y - shared.y) * (w.y - shared.y) > 0) {
          return false;
        }
        continue;
      }
      if (segments_meet(r[i], r[(i + 1) % n], r[j], r[(j + 1) % n])) return false;
    }
  }
  return true;
}

// A five-pointed star as a simple 10-vertex polygon, rounded to the lattice.
IRing five_pointed_star(std::mt19937_64& rng, IPoint c, std::int64_t outer) {
  for (Attempts t("five_pointed_star");; t.next()) {
    const double phase = 6.283185307179586 * uniform01(rng);
    const double inner = static_cast<double>(outer) * (0.35 + 0.15 * uniform01(rng));
    IRing r;
    for (int k = 0; k < 10; ++k) {
      const double t = phase + k * 3.141592653589793 / 5;
      const double rad = k % 2 == 0 ? static_cast<double>(outer) : inner;
      r.push_back({c.x + std::llround(rad * std::cos(t)), c.y + std::llround(rad * std::sin(t))});
    }
    if (is_simple(r) && twice_area(r) > 0) return r;
  }
}

}  // namespace

PolygonPair paper_figures(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"fig6_two_stars", "fig7_same_vertex_set", "fig8_three_parts",
                                              "fig9_three_holes", "fig10_collinear_point", "fig11_touching_edge",
                                              "fig12_touching_parts"});
  const std::int64_t s = uniform(rng, 1, 4);
  const auto sc = [&](std::vector<IRing> rings) {
    for (auto& r : rings) r = scaled(r, s);
    return rings;
  };
  LatticePair p;
  switch (v) {
    case 0: {
      const std::int64_t outer = uniform(rng, 12, 30);
      p.a = {five_pointed_star(rng, {0, 0}, outer)};
      p.b = {five_pointed_star(rng, {uniform(rng, outer / 3, outer), uniform(rng, -outer / 3, outer / 3)}, outer)};
      break;
    }
    case 1: {
      CaseSpec inner{"same_vertex_set", "two_centres", {}, rng()};
      return same_vertex_set(inner);
    }
    case 2: {
      // A: three triangles, two meeting at a vertex (irreducible parts of one polygon); two
      // of A's vertices lie on edges of B (vertex_on_edge from both sides).
      const std::int64_t w = 2 * uniform(rng, 5, 8), h = 2 * uniform(rng, 5, 8);
      p.b = sc({box(0, 0, w, h)});
      p.a = sc({{{w / 2, 0}, {w / 2 - 2, -4}, {w / 2 + 2, -4}},
                {{w, h / 2}, {w - 3, h / 2 - 2}, {w - 3, h / 2 + 2}},
                {{w / 2 - 2, -4}, {w / 2 - 6, -6}, {w / 2 - 4, -8}}});
      break;
    }
    case 3: {
      // A: three holes in a row sharing their bottom and top lines; B's edges run along
      // those lines or through the holes (holes_collinear).
      const std::int64_t y0 = 4, y1 = uniform(rng, 7, 9);
      p.a = sc({box(0, 0, 20, 12), box(2, y0, 6, y1), box(8, y0, 12, y1), box(14, y0, 18, y1)});
      p.b = sc({box(uniform(rng, 2, 6), y0 * uniform(rng, 0, 1), uniform(rng, 14, 18), uniform(rng, 8, 11))});
      break;
    }
    case 4: {
      // B's first part overlaps A's top edge (collinear_overlap, opposite directions), its
      // second touches A's corner (shared_vertex): non-regular A n B is a segment and a point.
      const std::int64_t a0 = uniform(rng, 1, 3);
      p.a = sc({box(0, 0, 4, 4)});
      p.b = sc({box(a0, 4, a0 + uniform(rng, 2, 4), 6), {{4, 0}, {6, -2}, {7, 0}}});
      break;
    }
    case 5: {
      // B overlaps A's corner and lies along part of A's top edge from outside
      // (shared_edge): the non-regular intersection has a dangling edge.
      p.a = sc({box(0, 0, 4, 4)});
      p.b = sc({{{2, 2}, {6, 2}, {6, 8}, {-2, 8}, {-2, 4}, {2, 4}}});
      break;
    }
    default: {
      // B's parts touch A at two corners and along one edge (shared_vertex, shared_edge).
      p.a = sc({box(0, 0, 4, 4)});
      p.b = sc({box(4, 4, 8, 8), box(4, -4, 8, 0), box(-4, 0, 0, 4)});
      if (uniform(rng, 0, 1) == 1) p.a_type = PolygonType::hole;
      break;
    }
  }
  return finish(rng, p);
}

}  // namespace mk::experiments
