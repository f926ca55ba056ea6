// OGC forms and exact OGC-style validity for the peer back ends. [MK89 §2.2] [OGC06-103 §6.1.11]
// Preconditions: see ogc.hpp.
#include "experiments/ogc.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>

#include "core/to_output.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "experiments/verdict.hpp"

namespace mk::experiments {

namespace {

int orientation(const Point& a, const Point& b, const Point& p) {
  const mpq_class ax(a.x), ay(a.y);
  return sgn((mpq_class(b.x) - ax) * (mpq_class(p.y) - ay) - (mpq_class(b.y) - ay) * (mpq_class(p.x) - ax));
}

bool in_box(const Point& a, const Point& b, const Point& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

enum class Side { inside, on, outside };

// Where the exact point (px, py) lies against ring s (crossing parity).
Side locate(const mpq_class& px, const mpq_class& py, const Ring& s) {
  bool in = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Point& a = s[i];
    const Point& b = s[(i + 1) % s.size()];
    const bool straddles = (a.y > py) != (b.y > py);
    const bool boxed = std::min(a.x, b.x) <= px && px <= std::max(a.x, b.x) && std::min(a.y, b.y) <= py &&
                       py <= std::max(a.y, b.y);
    if (!straddles && !boxed) continue;
    const mpq_class ax(a.x), ay(a.y);
    const int o = sgn((mpq_class(b.x) - ax) * (py - ay) - (mpq_class(b.y) - ay) * (px - ax));
    if (o == 0 && boxed) return Side::on;
    if (straddles && ((b.y > a.y) ? o > 0 : o < 0)) in = !in;
  }
  return in ? Side::inside : Side::outside;
}

// Whether ring r lies inside ring s (rings that do not cross), decided at the first vertex
// of r not on s, else at the first edge midpoint of r not on s; empty when all lie on s.
std::optional<bool> is_ring_inside(const Ring& r, const Ring& s) {
  for (const Point& p : r) {
    const Side side = locate(mpq_class(p.x), mpq_class(p.y), s);
    if (side != Side::on) return side == Side::inside;
  }
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point& a = r[i];
    const Point& b = r[(i + 1) % r.size()];
    const Side side = locate((mpq_class(a.x) + b.x) / 2, (mpq_class(a.y) + b.y) / 2, s);
    if (side != Side::on) return side == Side::inside;
  }
  return std::nullopt;
}

// Nesting depth of every ring (how many other rings contain it); empty when undecidable.
std::optional<std::vector<int>> depths(const std::vector<const Ring*>& rings) {
  std::vector<int> depth(rings.size(), 0);
  for (std::size_t i = 0; i < rings.size(); ++i) {
    for (std::size_t j = 0; j < rings.size(); ++j) {
      if (i == j) continue;
      const auto in = is_ring_inside(*rings[i], *rings[j]);
      if (!in) return std::nullopt;
      depth[i] += *in ? 1 : 0;
    }
  }
  return depth;
}

// Twice the signed area of a ring of doubles, exactly.
mpq_class twice_area(const Ring& r) {
  std::vector<RationalPoint> exact;
  for (const Point& p : r) exact.push_back(RationalKernel::point(p));
  return twice_signed_area(exact);
}

Ring without_repeats(const Ring& r) {
  Ring out;
  for (const Point& p : r) {
    if (out.empty() || !(out.back() == p)) out.push_back(p);
  }
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

}  // namespace

std::vector<Ring> vertex_complete(const std::vector<Ring>& rings) {
  std::vector<Point> all;
  for (const Ring& r : rings) all.insert(all.end(), r.begin(), r.end());
  std::sort(all.begin(), all.end(), [](const Point& p, const Point& q) { return p.x != q.x ? p.x < q.x : p.y < q.y; });
  all.erase(std::unique(all.begin(), all.end()), all.end());
  std::vector<Ring> out;
  for (const Ring& r : rings) {
    Ring c;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point& a = r[i];
      const Point& b = r[(i + 1) % r.size()];
      c.push_back(a);
      const auto lo = std::lower_bound(all.begin(), all.end(), std::min(a.x, b.x), [](const Point& p, double x) { return p.x < x; });
      std::vector<Point> inside;
      for (auto it = lo; it != all.end() && it->x <= std::max(a.x, b.x); ++it) {
        if (*it == a || *it == b || !in_box(a, b, *it)) continue;
        if (orientation(a, b, *it) == 0) inside.push_back(*it);
      }
      // Order along the edge from a: by the dominant coordinate's distance.
      const bool by_x = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
      std::sort(inside.begin(), inside.end(), [&](const Point& p, const Point& q) {
        return by_x ? std::abs(p.x - a.x) < std::abs(q.x - a.x) : std::abs(p.y - a.y) < std::abs(q.y - a.y);
      });
      c.insert(c.end(), inside.begin(), inside.end());
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::optional<MultiPolygon> ogc_form(const Polygon& p) {
  if (p.type != PolygonType::island) return std::nullopt;
  std::vector<const Ring*> rings;
  for (const Ring& r : p.rings) {
    if (r.size() < 3) return std::nullopt;
    rings.push_back(&r);
  }
  const auto depth = depths(rings);
  if (!depth) return std::nullopt;
  MultiPolygon out;
  std::vector<int> part_of(rings.size(), -1);
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if ((*depth)[i] % 2 != 0) continue;
    part_of[i] = static_cast<int>(out.size());
    out.push_back({*rings[i], {}});
  }
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if ((*depth)[i] % 2 == 0) continue;
    // The hole's shell: the ring one level up that contains it.
    int parent = -1;
    for (std::size_t j = 0; j < rings.size() && parent < 0; ++j) {
      if (j != i && (*depth)[j] == (*depth)[i] - 1 && is_ring_inside(*rings[i], *rings[j]).value_or(false)) {
        parent = part_of[j];
      }
    }
    if (parent < 0) return std::nullopt;
    out[static_cast<std::size_t>(parent)].holes.push_back(*rings[i]);
  }
  return out;
}

bool is_valid_ogc_exact(const MultiPolygon& polygons, std::string* why) {
  const auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  std::vector<Ring> rings;
  std::vector<bool> is_hole;
  std::vector<std::size_t> part;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const auto add = [&](const Ring& r, bool hole) {
      rings.push_back(without_repeats(r));
      is_hole.push_back(hole);
      part.push_back(k);
    };
    add(polygons[k].shell, false);
    for (const Ring& h : polygons[k].holes) add(h, true);
  }
  for (std::size_t i = 0; i < rings.size(); ++i) {
    for (const Point& p : rings[i]) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return fail("a coordinate is not finite");
    }
    if (rings[i].size() < 3) return fail("ring " + std::to_string(i) + " has fewer than 3 distinct points");
    if (sgn(twice_area(rings[i])) == 0) return fail("ring " + std::to_string(i) + " has zero area");
  }
  const std::vector<Ring> complete = vertex_complete(rings);
  if (!is_valid_rounded_output<RationalKernel>(complete)) return fail("edges cross or overlap");
  // Orient shells counterclockwise and holes clockwise: the region on the left of every ring.
  Output oriented;
  for (std::size_t i = 0; i < complete.size(); ++i) {
    OutputIrreducible o;
    o.vertices = complete[i];
    if ((sgn(twice_area(o.vertices)) > 0) == static_cast<bool>(is_hole[i])) std::reverse(o.vertices.begin(), o.vertices.end());
    o.type = is_hole[i] ? PolygonType::hole : PolygonType::island;
    oriented.irreducible.push_back(std::move(o));
  }
  if (have_overlapping_sectors(oriented, true)) return fail("regions overlap where rings meet");
  std::vector<const Ring*> ptrs;
  for (const Ring& r : rings) ptrs.push_back(&r);
  const auto depth = depths(ptrs);
  if (!depth) return fail("a ring lies entirely on another ring");
  for (std::size_t i = 0; i < rings.size(); ++i) {
    const bool odd = (*depth)[i] % 2 != 0;
    if (odd != is_hole[i]) return fail(std::string(is_hole[i] ? "a hole lies outside its shell" : "a shell lies inside another polygon"));
    if (is_hole[i]) {
      std::size_t shell = 0;  // the part's first ring
      while (part[shell] != part[i]) ++shell;
      if (!is_ring_inside(rings[i], rings[shell]).value_or(false)) return fail("a hole lies outside its own shell");
    }
  }
  return true;
}

}  // namespace mk::experiments
