// Integer shapes on a small grid for the test families (see grid_shapes.hpp).
// [BRIEF §1] [MK89 §2.2]
// Preconditions: see grid_shapes.hpp.
#include "tests/oracle/grid_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace mk::oracle::grid {

namespace {

int orient(const IP& o, const IP& a, const IP& b) {
  const Int c = (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  return (c > 0) - (c < 0);
}

// Whether two edges of one polygon cross properly (outside mkbool's input domain; touching
// and collinear overlaps are allowed: prepare() makes them vertex-complete).
bool has_crossing(const IPoly& p) {
  std::vector<std::pair<IP, IP>> edges;
  for (const auto& r : p.rings) {
    for (std::size_t i = 0; i < r.size(); ++i) edges.push_back({r[i], r[(i + 1) % r.size()]});
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto& [a, b] = edges[i];
      const auto& [c, d] = edges[j];
      if (orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0) return true;
    }
  }
  return false;
}

bool is_on_segment(const IP& a, const IP& b, const IP& p) {
  return orient(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Whether ring r has boundary points strictly inside ring s and strictly outside it: r
// crosses s, if not properly then through points they share (a vertex of one on the other,
// or a shared vertex where their sectors interleave), which nesting cannot describe. Tested
// at the midpoints of r's edges cut at s's vertices, in doubled coordinates.
bool crosses_through_contacts(const IRing& r, const IRing& s) {
  bool inside = false, outside = false;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const IP& a = r[i];
    const IP& b = r[(i + 1) % r.size()];
    std::vector<IP> cut{a, b};
    for (const IP& v : s) {
      if (is_on_segment(a, b, v)) cut.push_back(v);
    }
    std::sort(cut.begin(), cut.end());
    cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
    for (std::size_t k = 0; k + 1 < cut.size(); ++k) {
      const IP m{cut[k].x + cut[k + 1].x, cut[k].y + cut[k + 1].y};  // twice the midpoint
      bool on = false, in = false;
      for (std::size_t j = 0; j < s.size(); ++j) {
        const IP u{2 * s[j].x, 2 * s[j].y};
        const IP w{2 * s[(j + 1) % s.size()].x, 2 * s[(j + 1) % s.size()].y};
        if (is_on_segment(u, w, m)) on = true;
        if ((u.y > m.y) != (w.y > m.y) && (w.y > u.y ? orient(u, w, m) > 0 : orient(u, w, m) < 0)) in = !in;
      }
      if (on) continue;
      (in ? inside : outside) = true;
    }
  }
  return inside && outside;
}

Int twice_area(const IRing& r) {
  Int s = 0;
  for (std::size_t i = 0; i < r.size(); ++i) s += r[i].x * r[(i + 1) % r.size()].y - r[(i + 1) % r.size()].x * r[i].y;
  return s;
}

}  // namespace

Int uniform(Rng& rng, Int lo, Int hi) { return std::uniform_int_distribution<Int>(lo, hi)(rng); }
bool chance(Rng& rng, int one_in) { return uniform(rng, 0, one_in - 1) == 0; }

// Outside mkbool's model: a proper crossing, or two rings crossing through a contact.
bool is_outside_the_model(const IPoly& p) {
  if (has_crossing(p)) return true;
  for (std::size_t i = 0; i < p.rings.size(); ++i) {
    for (std::size_t j = 0; j < p.rings.size(); ++j) {
      if (i != j && crosses_through_contacts(p.rings[i], p.rings[j])) return true;
    }
  }
  return false;
}

bool is_same_set(IRing a, IRing b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

// The convex hull (counterclockwise, no collinear points) of pts.
IRing convex_hull(std::vector<IP> pts) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return {};
  IRing h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && orient(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && orient(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h.size() >= 3 ? h : IRing{};
}

IRing random_convex(Rng& rng, Int x0, Int y0, Int x1, Int y1, int points) {
  for (;;) {
    std::vector<IP> pts;
    for (int i = 0; i < points; ++i) pts.push_back({uniform(rng, x0, x1), uniform(rng, y0, y1)});
    IRing h = convex_hull(pts);
    if (!h.empty()) return h;
  }
}

// A star-shaped ring around the half-integer centre (cx + 1/2, cy + 1/2): integer points at
// random radii, sorted by angle around the centre, one per direction (simple by
// construction when every gap is below half a turn, which is checked).
IRing random_star(Rng& rng, Int cx, Int cy, int rmin, int rmax, int n) {
  for (;;) {
    std::vector<IP> pts;
    std::uniform_real_distribution<double> angle(0, 6.283185307179586);
    for (int i = 0; i < n; ++i) {
      const double t = angle(rng);
      const double r = static_cast<double>(uniform(rng, rmin, rmax));
      pts.push_back({cx + static_cast<Int>(std::lround(r * std::cos(t))), cy + static_cast<Int>(std::lround(r * std::sin(t)))});
    }
    // Directions from the centre, doubled to stay integral: 2p - (2c + 1).
    const auto dir = [&](const IP& p) { return IP{2 * p.x - 2 * cx - 1, 2 * p.y - 2 * cy - 1}; };
    const auto upper = [](const IP& d) { return d.y > 0 || (d.y == 0 && d.x > 0); };
    const auto cross = [](const IP& u, const IP& v) { return u.x * v.y - u.y * v.x; };
    std::sort(pts.begin(), pts.end(), [&](const IP& a, const IP& b) {
      const IP da = dir(a), db = dir(b);
      if (upper(da) != upper(db)) return upper(da);
      return cross(da, db) > 0;
    });
    IRing out;
    for (const IP& p : pts) {
      if (!out.empty() && upper(dir(out.back())) == upper(dir(p)) && cross(dir(out.back()), dir(p)) == 0) continue;
      out.push_back(p);
    }
    bool ok = out.size() >= 3;
    for (std::size_t i = 0; ok && i < out.size(); ++i) ok = cross(dir(out[i]), dir(out[(i + 1) % out.size()])) > 0;
    if (ok) return out;
  }
}

// ---- cell sets: multi-part inputs sharing edges, and the boundaries of cell sets, which
// touch themselves at repeated vertices where two cells meet only at a corner.

Cells random_cells(Rng& rng, Int w, Int h, int percent) {
  Cells c;
  for (Int x = 0; x < w; ++x) {
    for (Int y = 0; y < h; ++y) {
      if (uniform(rng, 0, 99) < percent) c.insert({x, y});
    }
  }
  if (c.empty()) c.insert({uniform(rng, 0, w - 1), uniform(rng, 0, h - 1)});
  return c;
}

// Each cell its own square ring: parts that share whole edges (shared_edge between parts).
IPoly cells_as_parts(const Cells& cells, Int s) {
  IPoly p;
  for (const auto& [x, y] : cells) {
    p.rings.push_back({{x * s, y * s}, {x * s + s, y * s}, {x * s + s, y * s + s}, {x * s, y * s + s}});
  }
  return p;
}

// The boundary of a cell set as rings, the region on their left. Where two cells meet only
// at a corner the trace either turns away (separate rings touching at the vertex) or
// passes straight through (`through`: one ring visiting the vertex twice). Collinear
// points are kept or dropped at random (redundant_collinear vertices).
IPoly cells_as_boundary(const Cells& cells, Int s, bool through, Rng& rng) {
  std::multimap<IP, IP> out_edges;  // unit edges, region on the left
  const auto in = [&](Int x, Int y) { return cells.count({x, y}) > 0; };
  for (const auto& [x, y] : cells) {
    if (!in(x, y - 1)) out_edges.insert({{x, y}, {x + 1, y}});
    if (!in(x + 1, y)) out_edges.insert({{x + 1, y}, {x + 1, y + 1}});
    if (!in(x, y + 1)) out_edges.insert({{x + 1, y + 1}, {x, y + 1}});
    if (!in(x - 1, y)) out_edges.insert({{x, y + 1}, {x, y}});
  }
  IPoly p;
  while (!out_edges.empty()) {
    auto it = out_edges.begin();
    const IP start = it->first;
    IRing ring{start};
    IP prev = start, cur = it->second;
    out_edges.erase(it);
    while (!(cur == start)) {
      ring.push_back(cur);
      auto [lo, hi] = out_edges.equal_range(cur);
      auto pick = lo;
      if (std::next(lo) != hi) {  // a corner shared by two diagonal cells: two ways on
        const IP din{cur.x - prev.x, cur.y - prev.y};
        for (auto e = lo; e != hi; ++e) {
          const IP dout{e->second.x - cur.x, e->second.y - cur.y};
          const Int turn = din.x * dout.y - din.y * dout.x;  // > 0: left
          if ((turn < 0) == through) pick = e;  // right: into the other cell
        }
      }
      prev = cur;
      cur = pick->second;
      out_edges.erase(pick);
    }
    // Drop some collinear points (keep every point visited twice).
    IRing kept;
    std::map<IP, int> visits;
    for (const IP& v : ring) ++visits[v];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const IP& a = ring[(i + ring.size() - 1) % ring.size()];
      const IP& b = ring[(i + 1) % ring.size()];
      if (visits[ring[i]] == 1 && orient(a, ring[i], b) == 0 && !chance(rng, 4)) continue;
      kept.push_back(ring[i]);
    }
    for (IP& v : kept) v = {v.x * s, v.y * s};
    p.rings.push_back(kept);
  }
  return p;
}

// ---- the families

IPoly grid_star(Rng& rng, Int cx, Int cy) {
  IPoly p;
  p.rings.push_back(random_star(rng, cx, cy, 2, 4, static_cast<int>(uniform(rng, 3, 9))));
  if (chance(rng, 3)) {  // a star hole around the same centre
    IPoly q = p;
    q.rings.push_back(random_star(rng, cx, cy, 1, 1, static_cast<int>(uniform(rng, 3, 6))));
    if (!is_outside_the_model(q)) p = q;
  }
  if (chance(rng, 3)) {  // a second part beside it
    IPoly q = p;
    q.rings.push_back(random_star(rng, cx + 5, cy + uniform(rng, -2, 2), 1, 2, static_cast<int>(uniform(rng, 3, 6))));
    if (!is_outside_the_model(q)) p = q;
  }
  return p;
}

// Shells with holes touching the shell at a vertex or on an edge, and each other at a
// vertex (holes_touching); sometimes an island inside a hole.
IPoly holes_touching(Rng& rng) {
  const Int w = 2 * uniform(rng, 3, 5), h = 2 * uniform(rng, 3, 5);
  IPoly p;
  p.rings.push_back({{0, 0}, {w / 2, 0}, {w, 0}, {w, h}, {0, h}});  // (w/2, 0) a point holes may touch
  const int holes = static_cast<int>(uniform(rng, 1, 4));
  for (int attempt = 0, made = 0; made < holes && attempt < 40; ++attempt) {
    IP touch;
    switch (uniform(rng, 0, 3)) {
      case 0: touch = p.rings[0][static_cast<std::size_t>(uniform(rng, 0, 4))]; break;  // a shell vertex
      case 1: touch = {uniform(rng, 1, w - 1), h}; break;                             // on a shell edge
      case 2:  // a vertex of an earlier hole
        if (p.rings.size() > 1) {
          const IRing& r = p.rings[static_cast<std::size_t>(uniform(rng, 1, static_cast<Int>(p.rings.size()) - 1))];
          touch = r[static_cast<std::size_t>(uniform(rng, 0, static_cast<Int>(r.size()) - 1))];
          break;
        }
        [[fallthrough]];
      default: touch = {uniform(rng, 1, w - 1), uniform(rng, 1, h - 1)};
    }
    IRing hole{touch, {uniform(rng, 1, w - 1), uniform(rng, 1, h - 1)}, {uniform(rng, 1, w - 1), uniform(rng, 1, h - 1)}};
    if (twice_area(hole) == 0) continue;
    IPoly q = p;
    q.rings.push_back(hole);
    // Rings may touch, share edges and nest (nesting is parity), but not cross, and a ring
    // twice would cancel itself.
    bool ok = !is_outside_the_model(q);
    for (std::size_t i = 1; ok && i < p.rings.size(); ++i) ok = !is_same_set(p.rings[i], hole);
    if (!ok) continue;
    p = q;
    ++made;
  }
  return p;
}

// Convex parts placed on a small grid, touching at vertices or along edges where they
// happen to; a part inside another becomes a hole by nesting (multi_part).
IPoly multi_part(Rng& rng) {
  IPoly p;
  const int parts = static_cast<int>(uniform(rng, 2, 4));
  for (int attempt = 0; static_cast<int>(p.rings.size()) < parts && attempt < 30; ++attempt) {
    const Int x = uniform(rng, 0, 6), y = uniform(rng, 0, 6);
    IPoly q = p;
    q.rings.push_back(random_convex(rng, x, y, x + uniform(rng, 1, 4), y + uniform(rng, 1, 4), 5));
    bool ok = !is_outside_the_model(q);
    for (std::size_t i = 0; ok && i < p.rings.size(); ++i) ok = !is_same_set(p.rings[i], q.rings.back());
    if (ok) p = q;
  }
  return p;
}

// Thin triangles around one apex, each from the apex to two neighbouring grid points of the
// square of half-width r around it (in angular order), the next one starting at the same
// point (sharing an edge) or one further: 4 r to 8 r parts meeting at the apex, so at least the
// 32 fragment ends from which steps 4 to 6 index a vertex (r >= 4). Shared edges lie inside
// the region; in a hole-type polygon they are dangling edges of its closed set.
IPoly fan(Rng& rng, IP apex, Int r) {  // r >= 4
  std::vector<IP> square;
  for (Int k = -r; k < r; ++k) {
    square.push_back({apex.x + k, apex.y - r});
    square.push_back({apex.x + r, apex.y + k});
    square.push_back({apex.x - k, apex.y + r});
    square.push_back({apex.x - r, apex.y - k});
  }
  // By angle around the apex: half-plane first, then the sign of the cross product.
  const auto upper = [&](const IP& p) { return p.y > apex.y || (p.y == apex.y && p.x > apex.x); };
  std::sort(square.begin(), square.end(), [&](const IP& a, const IP& b) {
    if (upper(a) != upper(b)) return upper(a);
    return (a.x - apex.x) * (b.y - apex.y) - (a.y - apex.y) * (b.x - apex.x) > 0;
  });
  IPoly p;
  for (std::size_t i = 0; i + 1 < square.size(); i += chance(rng, 2) ? 1 : 2) {
    p.rings.push_back({apex, square[i], square[i + 1]});
  }
  return p;
}
std::pair<IPoly, IPoly> fans(Rng& rng) {
  const IP apex{uniform(rng, 0, 2), uniform(rng, 0, 2)};
  // Mostly one apex; another one makes every pair of rays from the two cross (the oracle's
  // cost grows with the crossings).
  const IP other = chance(rng, 8) ? IP{apex.x + uniform(rng, -2, 2), apex.y + uniform(rng, -2, 2)} : apex;
  return {fan(rng, apex, 4), fan(rng, other, chance(rng, 2) ? 2 : 3)};  // B's apex indexed less often
}

// A convex polygon, and one whose vertices lie on its edges (vertex_on_edge): midpoints of
// its edges and points inside, on a doubled grid so that midpoints are integral.
std::pair<IPoly, IPoly> vertex_on_edge(Rng& rng) {
  const IRing a = random_convex(rng, 0, 0, 8, 8, 6);
  IRing a2;
  for (const IP& v : a) a2.push_back({2 * v.x, 2 * v.y});
  std::vector<IP> pts;
  for (std::size_t i = 0; i < a2.size(); ++i) {
    const IP& u = a2[i];
    const IP& v = a2[(i + 1) % a2.size()];
    if (!chance(rng, 3)) pts.push_back({(u.x + v.x) / 2, (u.y + v.y) / 2});
    if (chance(rng, 4)) pts.push_back(u);  // a shared vertex too
  }
  for (int i = 0; i < 2; ++i) pts.push_back({uniform(rng, 0, 16), uniform(rng, 0, 16)});
  IRing b = convex_hull(pts);
  if (b.empty()) b = {{0, 0}, {16, 0}, {0, 16}};
  return {IPoly{{a2}, false}, IPoly{{b}, false}};
}

}  // namespace mk::oracle::grid
