// Generators of exactly degenerate configurations on the integer lattice: shared_vertex,
// shared_edge, collinear_overlap, vertex_on_edge, identical, same_vertex_set, hole_filled,
// holes_collinear, nested_touching, collinear_vertices.
// [MK89 §2.2] (vertex-complete pairs) [MK89 §3.1 steps 2-4] (the cases vertex and fragment
// classification must get right) [MK89 Appendix A, Fig. 7] (same vertex set)
// Preconditions: none; every output pair is a valid input (no polygon crosses itself).
#include <algorithm>

#include "experiments/generator_util.hpp"
#include "experiments/generators.hpp"

namespace mk::experiments {

using detail::box;
using detail::finish;
using detail::LatticePair;
using detail::variant_index;

namespace {

IRing some_convex(std::mt19937_64& rng, std::int64_t scale = 1) {
  const auto radius = uniform(rng, 3, 30);
  return scaled(random_convex(rng, {0, 0}, radius, static_cast<int>(uniform(rng, 3, 10))), scale);
}

IRing some_star(std::mt19937_64& rng, std::int64_t scale = 1) {
  const int rmin = static_cast<int>(uniform(rng, 2, 10));
  return scaled(random_star(rng, {0, 0}, rmin, rmin + static_cast<int>(uniform(rng, 1, 20)),
                            static_cast<int>(uniform(rng, 3, 14))),
                scale);
}

// The hull of a and b and `count` random points strictly left of a -> b near their middle:
// a convex polygon with the edge ab (or a vertex at a, when b == a).
IRing hull_left_of(std::mt19937_64& rng, IPoint a, IPoint b, IPoint line_a, IPoint line_b, std::int64_t reach) {
  for (Attempts t("hull_left_of");; t.next()) {
    std::vector<IPoint> pts{a, b};
    const IPoint mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
    for (int i = 0; i < uniform(rng, 1, 6); ++i) pts.push_back(random_point_left_of(rng, line_a, line_b, mid, reach));
    IRing h = convex_hull(pts);
    if (h.size() >= 3) return h;
  }
}

IPoint random_inside(std::mt19937_64& rng, const IRing& convex, std::int64_t reach, std::int64_t parity = 1) {
  for (Attempts t("random_inside");; t.next()) {
    const IPoint p{parity * uniform(rng, -reach, reach), parity * uniform(rng, -reach, reach)};
    if (is_strictly_inside_convex(convex, p)) return p;
  }
}

}  // namespace

PolygonPair shared_vertex(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"outside", "rotated90", "star_rotated90"});
  const IRing a = v == 2 ? some_star(rng) : some_convex(rng);
  const IPoint p = a[static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(a.size()) - 1))];
  // outside: the point reflection through a vertex of a convex polygon meets it only there.
  const IRing b = v == 0 ? point_reflected(a, 2 * p) : rotated90(a, p);
  return finish(rng, {{a}, {b}});
}

PolygonPair shared_edge(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"opposite_side", "same_side", "star_reflected"});
  const IRing a = v == 2 ? some_star(rng) : some_convex(rng);
  const std::size_t i = static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(a.size()) - 1));
  const IPoint p = a[i], q = a[(i + 1) % a.size()];
  const std::int64_t reach = 5 + std::max(std::abs(q.x - p.x), std::abs(q.y - p.y));
  IRing b;
  if (v == 0) b = hull_left_of(rng, q, p, q, p, reach);  // a is counterclockwise: its outside
  if (v == 1) b = hull_left_of(rng, p, q, p, q, reach);
  if (v == 2) b = point_reflected(a, p + q);  // maps p <-> q: the edge as a set
  return finish(rng, {{a}, {b}});
}

PolygonPair collinear_overlap(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"same", "opposite"});
  const IRing a = some_convex(rng, 4);  // multiples of 4: quarter points stay on the lattice
  const std::size_t i = static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(a.size()) - 1));
  const IPoint p = a[i], q = a[(i + 1) % a.size()];
  const IPoint quarter{(q.x - p.x) / 4, (q.y - p.y) / 4};
  const std::int64_t t = uniform(rng, 1, 3);
  // same: a translate along the edge, whose copy of the edge overlaps it in the same
  // direction; opposite: the point reflection through a point of the edge's line, which
  // puts the copy on the other side, running the other way.
  const IRing b = v == 0 ? translated(a, t * quarter) : point_reflected(a, p + q + t * quarter);
  return finish(rng, {{a}, {b}});
}

PolygonPair vertex_on_edge(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"outside", "inside", "crossing"});
  const std::int64_t s = uniform(rng, 2, 5);
  // Scaled by 2s: the edge's s-th points are on the lattice, and so are interior points
  // (a lattice polygon scaled by 4 or more has some, by Pick's theorem).
  const IRing a = some_convex(rng, 2 * s);
  const std::size_t i = static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(a.size()) - 1));
  const IPoint p = a[i], q = a[(i + 1) % a.size()];
  const IPoint on = p + uniform(rng, 1, s - 1) * IPoint{(q.x - p.x) / s, (q.y - p.y) / s};  // inside pq
  const std::int64_t reach = 5 + std::max(std::abs(q.x - p.x), std::abs(q.y - p.y));
  IRing b;
  if (v == 0) b = hull_left_of(rng, on, on, q, p, reach);
  if (v == 1) {
    IPoint q1, q2;
    Attempts t("triangle");
    do {
      t.next();
      q1 = random_inside(rng, a, 80 * s);
      q2 = random_inside(rng, a, 80 * s);
    } while (orient(on, q1, q2) == 0);
    b = {on, q1, q2};
  }
  if (v == 2) {
    IPoint q1, q2;
    Attempts t("triangle");
    do {
      t.next();
      q1 = random_point_left_of(rng, p, q, on, reach);
      q2 = random_point_left_of(rng, q, p, on, reach);
    } while (orient(on, q1, q2) == 0);
    b = {on, q1, q2};
  }
  return finish(rng, {{a}, {b}});
}

PolygonPair identical(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"same", "shifted_start", "reversed", "with_hole_reversed"});
  const IRing a = some_star(rng);
  LatticePair p{{a}, {a}};
  if (v == 1) p.b = {shifted_start(a, static_cast<std::size_t>(uniform(rng, 1, static_cast<std::int64_t>(a.size()) - 1)))};
  if (v == 2) p.b = {reversed(a)};
  if (v == 3) {
    const IRing h = detail::hole_inside(rng, a, {0, 0}, 1);
    if (!h.empty()) p.a.push_back(h);
    p.b = p.a;
    for (auto& r : p.b) r = reversed(r);
  }
  return finish(rng, p, true);
}

namespace {

// The points in angular order around a half-integer centre (given doubled), or empty when
// two points share a direction or a gap reaches pi (the order is then no simple polygon).
IRing star_order(std::vector<IPoint> pts, IPoint twice_centre) {
  const auto dir = [&](IPoint p) { return IPoint{2 * p.x - twice_centre.x, 2 * p.y - twice_centre.y}; };
  const auto half = [](IPoint d) { return d.y > 0 || (d.y == 0 && d.x > 0) ? 0 : 1; };
  const auto cross = [](IPoint a, IPoint b) { return a.x * b.y - a.y * b.x; };
  std::sort(pts.begin(), pts.end(), [&](IPoint a, IPoint b) {
    const IPoint da = dir(a), db = dir(b);
    if (half(da) != half(db)) return half(da) < half(db);
    return cross(da, db) > 0;
  });
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (cross(dir(pts[i]), dir(pts[(i + 1) % pts.size()])) <= 0) return {};
  }
  return pts;
}

bool is_same_cycle(const IRing& r, const IRing& s) {
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (shifted_start(s, k) == r || reversed(shifted_start(s, k)) == r) return true;
  }
  return false;
}

}  // namespace

PolygonPair same_vertex_set(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  variant_index(spec, {"two_centres"});
  // [MK89 Appendix A, Fig. 7]: the same vertices ordered around two different centres.
  for (Attempts t("same_vertex_set", 1000);; t.next()) {
    const std::int64_t reach = uniform(rng, 4, 12);
    std::vector<IPoint> pts;
    for (int i = 0; i < uniform(rng, 5, 12); ++i) pts.push_back({uniform(rng, -reach, reach), uniform(rng, -reach, reach)});
    std::sort(pts.begin(), pts.end(), [](IPoint a, IPoint b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 4) continue;
    const auto centre = [&] { return IPoint{2 * uniform(rng, -reach / 2, reach / 2) + 1, 2 * uniform(rng, -reach / 2, reach / 2) + 1}; };
    IRing a, b;
    for (int t = 0; t < 20 && a.empty(); ++t) a = star_order(pts, centre());
    for (int t = 0; t < 40 && !a.empty(); ++t) {
      b = star_order(pts, centre());
      if (!b.empty() && !is_same_cycle(a, b)) return finish(rng, {{a}, {b}});
    }
  }
}

PolygonPair hole_filled(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"exact_fill", "reversed_fill", "larger_fill", "hole_type", "touching_vertex",
                                              "touching_twice", "touching_twice_overlap"});
  if (v >= 4) {
    // A hole touching the outer ring at one vertex, or at two (a chord of the outer ring
    // as one of its edges, so the region between them is pinched twice); B fills the hole
    // or overlaps both rings.
    IRing outer, hole;
    for (Attempts t("hole_filled: touching", 1000);; t.next()) {
      outer = scaled(random_convex(rng, {0, 0}, uniform(rng, 5, 12), static_cast<int>(uniform(rng, 5, 10))), 4);
      if (outer.size() < 4) continue;
      const std::size_t i = static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(outer.size()) - 1));
      const std::size_t j = (i + static_cast<std::size_t>(uniform(rng, 2, static_cast<std::int64_t>(outer.size()) - 2))) % outer.size();
      const IPoint q = random_inside(rng, outer, 60);
      const IPoint q2 = random_inside(rng, outer, 60);
      hole = v == 4 ? IRing{outer[i], q, q2} : IRing{outer[i], outer[j], q};
      // A triangle with its vertices on a convex ring or strictly inside it lies inside it.
      if (orient(hole[0], hole[1], hole[2]) != 0) break;
    }
    LatticePair p{{outer, hole}, {hole}};
    if (v == 6) p.b = {random_convex(rng, hole[2], uniform(rng, 8, 30), static_cast<int>(uniform(rng, 3, 8)))};
    return finish(rng, p);
  }
  IRing outer, hole;
  for (Attempts t("hole_filled", 1000); hole.empty(); t.next()) {
    outer = random_convex(rng, {0, 0}, uniform(rng, 20, 40), static_cast<int>(uniform(rng, 4, 10)));
    // Around the vertex average of a convex polygon, which lies inside it (up to rounding).
    IPoint c{0, 0};
    for (const IPoint v : outer) c = c + v;
    const auto n = static_cast<std::int64_t>(outer.size());
    hole = detail::hole_inside(rng, outer, {c.x / n, c.y / n}, uniform(rng, 3, 8));
  }
  LatticePair p{{outer, hole}, {hole}};
  if (v == 1) p.b = {reversed(hole)};
  if (v == 2) {
    // A polygon containing the hole and sharing some of its vertices and edges.
    std::vector<IPoint> pts = hole;
    for (int i = 0; i < uniform(rng, 1, 4); ++i) pts.push_back(random_inside(rng, outer, 40));
    p.b = {convex_hull(pts)};
  }
  if (v == 3) {
    p.a = {hole};
    p.a_type = PolygonType::hole;
  }
  return finish(rng, p);
}

PolygonPair holes_collinear(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"adjacent_holes", "overlapping_holes", "hole_on_boundary"});
  // Hole h1 of A; the hole h2 of B shares h1's right edge line (adjacent) or its bottom edge
  // line (overlapping); or B's outer boundary runs along h1's top edge.
  const std::int64_t x0 = uniform(rng, -10, 0), y0 = uniform(rng, -10, 0);
  const std::int64_t x1 = x0 + uniform(rng, 2, 8), y1 = y0 + uniform(rng, 2, 8);
  const IRing h1 = box(x0, y0, x1, y1);
  const IRing outer_a = box(x0 - uniform(rng, 1, 10), y0 - uniform(rng, 1, 10), x1 + uniform(rng, 12, 20),
                            y1 + uniform(rng, 1, 10));
  LatticePair p;
  p.a = {outer_a, h1};
  if (v == 0 || v == 1) {
    const std::int64_t bottom = v == 0 ? y0 + uniform(rng, -3, 3) : y0;
    const std::int64_t top = std::max(bottom + 1, y1 + uniform(rng, -1, 3));
    const IRing h2 = v == 0 ? box(x1, bottom, x1 + uniform(rng, 2, 8), top)
                            : box(x0 + uniform(rng, 1, x1 - x0 - 1), bottom, x1 + uniform(rng, 1, 8), top);
    const IRing outer_b = box(x0 - uniform(rng, 1, 10), y0 - uniform(rng, 5, 12), x1 + uniform(rng, 10, 20),
                              y1 + uniform(rng, 4, 12));
    p.b = {outer_b, h2};
  } else {
    const std::int64_t left = x0 + uniform(rng, -3, 1);
    p.b = {box(left, y1, std::max(left + 1, x1 + uniform(rng, -1, 3)), y1 + uniform(rng, 1, 6))};
  }
  return finish(rng, p);
}

PolygonPair nested_touching(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"vertex", "edge", "vertex_on_edge", "strictly_inside", "hole_type"});
  // Scaled by 8: midpoints, halvings and even interior points stay on the lattice.
  const IRing a = some_convex(rng, 8);
  const std::size_t i = static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(a.size()) - 1));
  const IPoint p = a[i], q = a[(i + 1) % a.size()];
  const IPoint mid{(p.x + q.x) / 2, (p.y + q.y) / 2};
  const auto triangle_at = [&](IPoint apex) {
    IPoint q1, q2;
    Attempts t("triangle");
    do {
      t.next();
      q1 = random_inside(rng, a, 240);
      q2 = random_inside(rng, a, 240);
    } while (orient(apex, q1, q2) == 0);
    return IRing{apex, q1, q2};
  };
  // The homothety with factor 1/2 about c (even coordinates keep it on the lattice).
  const auto half_towards = [&](IPoint c) {
    IRing out;
    for (const IPoint r : a) out.push_back({(r.x + c.x) / 2, (r.y + c.y) / 2});
    return out;
  };
  LatticePair out{{a}, {}};
  if (v == 0) out.b = {triangle_at(p)};
  if (v == 1 || v == 4) out.b = {half_towards(mid)};  // B's edge lies on A's edge
  if (v == 2) out.b = {triangle_at(mid)};
  if (v == 3) out.b = {half_towards(random_inside(rng, a, 120, 2))};
  if (v == 4) out.b_type = PolygonType::hole;
  return finish(rng, out);
}

PolygonPair collinear_vertices(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"same_region", "overlap"});
  const IRing a = some_star(rng, 4);
  // Redundant collinear vertices: the midpoints of some edges inserted.
  IRing with_midpoints;
  bool any = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    with_midpoints.push_back(a[i]);
    if (uniform(rng, 0, 1) == 1 || (!any && i + 1 == a.size())) {
      const IPoint q = a[(i + 1) % a.size()];
      with_midpoints.push_back({(a[i].x + q.x) / 2, (a[i].y + q.y) / 2});
      any = true;
    }
  }
  if (v == 0) return finish(rng, {{with_midpoints}, {a}});
  const std::size_t i = static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(a.size()) - 1));
  const IPoint d = a[(i + 1) % a.size()] - a[i];
  return finish(rng, {{with_midpoints}, {translated(with_midpoints, {d.x / 4, d.y / 4})}});
}

}  // namespace mk::experiments
