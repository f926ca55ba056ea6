// Random input pairs in families that stress the algorithm, moved off the integer grid by
// exact transforms (see families.hpp). [BRIEF §1] [BRIEF §5] [MK89 §2.2]
// Preconditions: see families.hpp.
#include "tests/oracle/families.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "tests/oracle/grid_shapes.hpp"

namespace mk::oracle {

namespace {

using namespace grid;

// ---- exact transforms off the grid

struct Transform {
  Int m00 = 1, m01 = 0, m10 = 0, m11 = 1;  // integer matrix: a rotation by a Pythagorean angle times c
  Int tx = 0, ty = 0;                      // translation, in grid units after the matrix
  int k = 0;                               // scaling by 2^k
  std::string name;
};

Transform random_transform(Rng& rng, Int extent) {
  Transform t;
  static constexpr std::array<std::array<Int, 3>, 6> kTriples{
      {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}, {119, 120, 169}}};
  if (!chance(rng, 3)) {
    const auto& [a, b, c] = kTriples[static_cast<std::size_t>(uniform(rng, 0, kTriples.size() - 1))];
    const Int sa = chance(rng, 2) ? a : b, sb = sa == a ? b : a;
    const Int sign = chance(rng, 2) ? 1 : -1;
    t.m00 = sa, t.m01 = -sign * sb, t.m10 = sign * sb, t.m11 = sa;
    t.name = "rot(" + std::to_string(sa) + "," + std::to_string(sign * sb) + "," + std::to_string(c) + ")";
    extent *= c;
  }
  if (chance(rng, 4)) {  // mirror: the rings turn the other way
    t.m01 = -t.m01, t.m11 = -t.m11;
    t.name += t.name.empty() ? "mirror" : " mirror";
  }
  if (chance(rng, 4)) {  // far from the origin: coordinates of 40 bits, differences of a few
    t.tx = uniform(rng, -(Int{1} << 40), Int{1} << 40);
    t.ty = uniform(rng, -(Int{1} << 40), Int{1} << 40);
    t.name += " +(" + std::to_string(t.tx) + "," + std::to_string(t.ty) + ")";
    extent += Int{1} << 40;
  }
  // 2^k for k across the exponent range: the extremes, the subnormal range, and anywhere.
  const int bits = static_cast<int>(std::ceil(std::log2(static_cast<double>(extent) + 1)));
  static constexpr int kExtremes[] = {-1074, -1060, -1022, -1000, 1000, -500, 500, -1, 1};
  switch (uniform(rng, 0, 3)) {
    case 0: t.k = 0; break;
    case 1: t.k = kExtremes[uniform(rng, 0, std::size(kExtremes) - 1)]; break;
    default: t.k = static_cast<int>(uniform(rng, -1074, 1000));
  }
  t.k = std::min(t.k, 1023 - bits);  // stay below the largest double
  if (t.k != 0) t.name += " 2^" + std::to_string(t.k);
  if (t.name.empty()) t.name = "grid";
  if (t.name[0] == ' ') t.name.erase(0, 1);
  return t;
}

Polygon apply(const Transform& t, const IPoly& p, Rng& rng) {
  Polygon out;
  out.type = p.hole ? PolygonType::hole : PolygonType::island;
  for (const IRing& r : p.rings) {
    Ring ring;
    for (const IP& v : r) {
      const Int x = t.m00 * v.x + t.m01 * v.y + t.tx;
      const Int y = t.m10 * v.x + t.m11 * v.y + t.ty;
      // Exact: |x|, |y| < 2^53, and 2^k keeps them representable (k >= -1074 and the
      // largest stays below 2^1024).
      ring.push_back({std::ldexp(static_cast<double>(x), t.k), std::ldexp(static_cast<double>(y), t.k)});
    }
    // Any start, either direction (orientation comes from nesting: deviation 2).
    std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(uniform(rng, 0, static_cast<Int>(ring.size()) - 1)), ring.end());
    if (chance(rng, 3)) std::reverse(ring.begin(), ring.end());
    out.rings.push_back(std::move(ring));
  }
  std::shuffle(out.rings.begin(), out.rings.end(), rng);
  return out;
}

Int extent(const IPoly& p) {
  Int e = 1;
  for (const auto& r : p.rings) {
    for (const IP& v : r) e = std::max({e, v.x < 0 ? -v.x : v.x, v.y < 0 ? -v.y : v.y});
  }
  return e;
}

void maybe_hole_type(Rng& rng, IPoly& p) { p.hole = chance(rng, 4); }

std::pair<IPoly, IPoly> make_family(const std::string& name, Rng& rng) {
  if (name == "grid_stars") {
    return {grid_star(rng, uniform(rng, 1, 5), uniform(rng, 1, 5)), grid_star(rng, uniform(rng, 1, 5), uniform(rng, 1, 5))};
  }
  if (name == "cell_parts") {  // parts sharing edges; B on the same grid or shifted by one cell
    const Cells a = random_cells(rng, uniform(rng, 2, 4), uniform(rng, 2, 4), 50);
    Cells b = random_cells(rng, uniform(rng, 2, 4), uniform(rng, 2, 4), 50);
    return {cells_as_parts(a, 1), chance(rng, 2) ? cells_as_parts(b, 1) : cells_as_boundary(b, 1, false, rng)};
  }
  if (name == "self_touching") {  // cell-set boundaries passing their diagonal corners twice
    const Int w = uniform(rng, 2, 5), h = uniform(rng, 2, 5);
    return {cells_as_boundary(random_cells(rng, w, h, 55), 2, true, rng),
            cells_as_boundary(random_cells(rng, w, h, 55), chance(rng, 2) ? 2 : 1, chance(rng, 2), rng)};
  }
  if (name == "collinear_overlap") {  // boundaries on the same lines, half a cell apart
    const Cells a = random_cells(rng, uniform(rng, 2, 4), uniform(rng, 2, 4), 60);
    IPoly pa = cells_as_boundary(a, 2, chance(rng, 2), rng);
    IPoly pb = cells_as_boundary(random_cells(rng, uniform(rng, 2, 4), uniform(rng, 2, 4), 60), 2, chance(rng, 2), rng);
    const IP shift{chance(rng, 2) ? 1 : 0, chance(rng, 2) ? 1 : 0};
    for (auto& r : pb.rings) {
      for (IP& v : r) v = {v.x + shift.x, v.y + shift.y};
    }
    return {pa, pb};
  }
  if (name == "vertex_on_edge") return vertex_on_edge(rng);
  if (name == "identical") {  // B = A: the same rings, reversed, restarted, or A turned into a hole
    const std::string others[] = {"grid_stars", "cell_parts", "self_touching", "holes_touching", "multi_part",     "fans"};
    IPoly a = make_family(others[uniform(rng, 0, 4)], rng).first;
    IPoly b = a;
    for (auto& r : b.rings) {
      if (chance(rng, 2)) std::reverse(r.begin(), r.end());
    }
    return {a, b};
  }
  if (name == "holes_touching") return {holes_touching(rng), holes_touching(rng)};
  if (name == "multi_part") return {multi_part(rng), multi_part(rng)};
  if (name == "fans") return fans(rng);  // thousands of fragment ends at one vertex, scaled down
  return {grid_star(rng, 3, 3), grid_star(rng, 3, 3)};
}

std::string number(double v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

}  // namespace

const std::vector<std::string>& family_names() {
  static const std::vector<std::string> names{"grid_stars",     "cell_parts",     "self_touching",
                                              "collinear_overlap", "vertex_on_edge", "identical",
                                              "holes_touching", "multi_part",     "fans"};
  return names;
}

GeneratedPair random_pair(std::size_t index, Rng& rng) {
  const std::string& family = family_names()[index % family_names().size()];
  auto [a, b] = make_family(family, rng);
  maybe_hole_type(rng, a);
  maybe_hole_type(rng, b);
  if (family == "identical" && chance(rng, 3)) b.hole = !a.hole;  // the complement, touching everywhere
  Transform t = random_transform(rng, std::max(extent(a), extent(b)));
  if (family == "fans" && t.k != 0) {  // fans stress degree, not the exponent range, and their
    const auto at = t.name.rfind("2^");  // hundreds of crossings at 2^-1000 cost the oracle seconds
    t.name = at == 0 ? "grid" : t.name.substr(0, at - 1);
    t.k = 0;
  }
  if (std::getenv("MK_ORACLE_GRID") != nullptr) t = Transform{1, 0, 0, 1, 0, 0, 0, "grid"};  // debugging aid
  GeneratedPair out{family, t.name, apply(t, a, rng), apply(t, b, rng)};
  if (chance(rng, 2)) std::swap(out.a, out.b);
  return out;
}

std::string describe(const Polygon& p) {
  std::string s = p.type == PolygonType::island ? "island[" : "hole[";
  for (const auto& r : p.rings) {
    s += "(";
    for (std::size_t i = 0; i < r.size(); ++i) s += (i ? ", " : "") + number(r[i].x) + " " + number(r[i].y);
    s += ")";
  }
  return s + "]";
}

}  // namespace mk::oracle
