// Fill rules, union-all and intersection-all checked against independent references: the
// winding-number oracle (winding.hpp) at sample points for every rule and operation on
// random self-crossing inputs, and CGAL Epeck's Boolean operations (join, intersection) on
// random sets of valid polygons. `exact` and `rational` must give identical output.
// [BRIEF §1, extended by issue 13] [BRIEF §3] (exact kernels agree on every input)
// Preconditions: CGAL 5.5. Environment: MK_ORACLE_SEED (a number, or "random"),
// MK_FILL_CASES (random self-crossing inputs; default 5000 in Release, 300 under the
// sanitizers; a twentieth of them non-regular), MK_FILL_SETS (random union-all sets; default 200, 40 under the sanitizers).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "api/mkbool.hpp"
#include "core/canonical.hpp"
#include "tests/oracle/cgal_reference.hpp"
#include "tests/oracle/families.hpp"
#include "tests/oracle/winding.hpp"

namespace mk::oracle {
namespace {

#ifdef MK_SANITIZE_BUILD
constexpr long kDefaultCases = 300;
constexpr long kDefaultSets = 40;
#else
constexpr long kDefaultCases = 5000;
constexpr long kDefaultSets = 200;
#endif

using Rng = std::mt19937_64;

std::uint64_t seed() {
  const char* s = std::getenv("MK_ORACLE_SEED");
  if (s == nullptr || *s == '\0') return 20261125;
  if (std::string(s) == "random") return std::random_device{}();
  return std::strtoull(s, nullptr, 10);
}

long count_from(const char* name, long fallback) {
  const char* s = std::getenv(name);
  return s == nullptr || *s == '\0' ? fallback : std::strtol(s, nullptr, 10);
}

long uniform(Rng& rng, long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); }
bool chance(Rng& rng, int one_in) { return uniform(rng, 0, one_in - 1) == 0; }

// ---- self-crossing inputs on a small grid (dense coincidences), then moved off it exactly

Ring random_ring(Rng& rng, int grid, int n) {
  Ring r;
  for (int i = 0; i < n; ++i) r.push_back({double(uniform(rng, 0, grid)), double(uniform(rng, 0, grid))});
  return r;
}

Ring bowtie(Rng& rng) {
  const double x = double(uniform(rng, 0, 3)), y = double(uniform(rng, 0, 3)), s = double(uniform(rng, 1, 4));
  return {{x, y}, {x + s, y + s}, {x + s, y}, {x, y + s}};
}

// A star polygon {5/2} (pentagram) or {7/3} on grid points around a centre.
Ring star(Rng& rng) {
  static const std::array<std::array<double, 2>, 5> five{{{4, 0}, {6, 6}, {8, 0}, {3, 4}, {9, 4}}};
  static const std::array<std::array<double, 2>, 7> seven{{{5, 0}, {2, 7}, {8, 6}, {1, 2}, {9, 2}, {2, 6}, {8, 7}}};
  Ring r;
  if (chance(rng, 2)) {
    for (const auto& p : five) r.push_back({p[0], p[1]});
  } else {
    for (const auto& p : seven) r.push_back({p[0], p[1]});
  }
  return r;
}

Ring rectangle(Rng& rng, int grid) {
  const double x0 = double(uniform(rng, 0, grid - 1)), y0 = double(uniform(rng, 0, grid - 1));
  const double x1 = double(uniform(rng, long(x0) + 1, grid)), y1 = double(uniform(rng, long(y0) + 1, grid));
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

void maybe_reverse(Rng& rng, Ring& r) {
  if (chance(rng, 2)) std::reverse(r.begin(), r.end());
  std::rotate(r.begin(), r.begin() + uniform(rng, 0, long(r.size()) - 1), r.end());
}

const std::vector<std::string> kFamilies = {"random_crossing", "bowtie",          "star",
                                            "traced_twice",    "overlapping_parts", "figure_eight",
                                            "collinear_spikes"};

Polygon self_crossing_input(const std::string& family, Rng& rng) {
  Polygon p;
  if (family == "random_crossing") {
    p.rings.push_back(random_ring(rng, 6, int(uniform(rng, 3, 8))));
    if (chance(rng, 3)) p.rings.push_back(random_ring(rng, 6, int(uniform(rng, 3, 5))));
  } else if (family == "bowtie") {
    p.rings.push_back(bowtie(rng));
  } else if (family == "star") {
    p.rings.push_back(star(rng));
  } else if (family == "traced_twice") {  // winding 2, or 1 with the ring again reversed
    Ring r = chance(rng, 2) ? rectangle(rng, 6) : random_ring(rng, 6, 4);
    Ring twice = r;
    twice.insert(twice.end(), r.begin(), r.end());
    p.rings.push_back(twice);
    if (chance(rng, 3)) p.rings.push_back(Ring(r.rbegin(), r.rend()));
  } else if (family == "overlapping_parts") {
    for (long k = uniform(rng, 2, 4); k > 0; --k) p.rings.push_back(rectangle(rng, 6));
  } else if (family == "figure_eight") {  // a ring repeating a vertex, loops either way
    const double c = double(uniform(rng, 2, 4));
    p.rings.push_back({{0, 0}, {c, 0}, {c, c}, {2 * c, c}, {2 * c, 2 * c}, {c, 2 * c}, {c, c}, {0, c}});
  } else {  // collinear_spikes: edges running back along themselves, overlapping others
    p.rings.push_back({{0, 0}, {4, 0}, {2, 0}, {2, 3}, {0, 3}});
    p.rings.push_back(rectangle(rng, 5));
  }
  for (Ring& r : p.rings) maybe_reverse(rng, r);
  return p;
}

// An exact similarity: optional rotation by the Pythagorean angle (3, 4, 5) (times 5),
// shift, and scaling by 2^k.
void transform(Rng& rng, Polygon& a, Polygon& b) {
  const bool rotate = chance(rng, 3);
  const int k = chance(rng, 2) ? 0 : int(uniform(rng, -600, 600));
  const double dx = double(uniform(rng, -3, 3)), dy = double(uniform(rng, -3, 3));
  for (Polygon* p : {&a, &b}) {
    for (Ring& r : p->rings) {
      for (Point& q : r) {
        Point t = rotate ? Point{3 * q.x - 4 * q.y, 4 * q.x + 3 * q.y} : q;
        if (p == &b) t = {t.x + dx, t.y + dy};
        q = {std::ldexp(t.x, k), std::ldexp(t.y, k)};
      }
    }
  }
}

std::vector<QRing> q_rings(const Polygon& p) {
  std::vector<QRing> out;
  for (const Ring& r : p.rings) {
    QRing q;
    for (const Point& v : r) q.push_back({Q(v.x), Q(v.y)});
    out.push_back(std::move(q));
  }
  return out;
}

// The result as a region (exact coordinates): its polygons and, in a non-regular result, its
// two-sided parts (2-point rings) and one-sided parts (1-point rings), which bound no face;
// and a canonical form of its irreducible polygons for comparing kernels.
Region region_of_output(const Output& o) {
  Region r;
  r.complement = o.unbounded;
  for (const auto& c : o.irreducible) {
    QRing ring;
    for (std::size_t i = 0; i < c.vertices.size(); ++i) ring.push_back({Q(c.exact[2 * i]), Q(c.exact[2 * i + 1])});
    r.rings.push_back(std::move(ring));
  }
  return r;
}

std::vector<CanonicalCycle<std::string>> canonical_output(const Output& o) {
  std::vector<CanonicalCycle<std::string>> out;
  for (const auto& c : o.irreducible) {
    auto& [type, vs] = out.emplace_back();
    type = c.type;
    for (std::size_t i = 0; i < c.vertices.size(); ++i) vs.push_back(c.exact[2 * i] + " " + c.exact[2 * i + 1]);
  }
  return canonical(std::move(out));
}

// Points near every vertex (input and result), beside the midpoint of every input edge,
// and random points of the bounding box: any point on no ring is a valid sample.
std::vector<QPoint> samples_near(const std::vector<QRing>& inputs, const Region& result, Rng& rng, std::size_t max) {
  std::vector<QPoint> vertices;
  Q lo_x, lo_y, hi_x, hi_y;
  bool first = true;
  for (const auto* rings : {&inputs, &result.rings}) {
    for (const QRing& r : *rings) {
      for (const QPoint& p : r) {
        vertices.push_back(p);
        if (first || p.x < lo_x) lo_x = p.x;
        if (first || p.y < lo_y) lo_y = p.y;
        if (first || p.x > hi_x) hi_x = p.x;
        if (first || p.y > hi_y) hi_y = p.y;
        first = false;
      }
    }
  }
  std::vector<QPoint> out;
  if (first) return out;
  Q eps = (hi_x - lo_x + hi_y - lo_y + 1) / Q(1 << 24);
  for (const QPoint& p : vertices) {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        if (dx != 0 || dy != 0) out.push_back({p.x + dx * eps, p.y + dy * eps * 3 / 2});
      }
    }
  }
  for (const QRing& r : inputs) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      const QPoint& a = r[i];
      const QPoint& b = r[(i + 1) % r.size()];
      const QPoint m{(a.x + b.x) / 2, (a.y + b.y) / 2};
      out.push_back({m.x - (b.y - a.y) / Q(1 << 20), m.y + (b.x - a.x) / Q(1 << 20)});
      out.push_back({m.x + (b.y - a.y) / Q(1 << 20), m.y - (b.x - a.x) / Q(1 << 20)});
    }
  }
  for (int i = 0; i < 8; ++i) {
    const Q fx(uniform(rng, 0, 1 << 20), 1 << 20), fy(uniform(rng, 0, 1 << 20), 1 << 20);
    out.push_back({lo_x + (hi_x - lo_x) * fx, lo_y + (hi_y - lo_y) * fy});
  }
  std::shuffle(out.begin(), out.end(), rng);
  if (out.size() > max) out.resize(max);
  return out;
}

constexpr Operation kOps[] = {Operation::intersection, Operation::union_, Operation::difference,
                              Operation::symmetric_difference};
constexpr Rule kRules[] = {Rule::evenodd, Rule::nonzero, Rule::positive, Rule::negative};

FillRule to_fill_rule(Rule r) {
  switch (r) {
    case Rule::evenodd: return FillRule::evenodd;
    case Rule::nonzero: return FillRule::nonzero;
    case Rule::positive: return FillRule::positive;
    case Rule::negative: return FillRule::negative;
  }
  return FillRule::evenodd;
}

// Random case i: two self-crossing inputs of the families, moved together exactly, with
// their rings in rationals and a description for failure messages.
struct DrawnCase {
  Polygon a, b;
  std::vector<QRing> qa, qb;
  std::string what;
};

DrawnCase draw_case(long i, Rng& rng) {
  const std::string fa = kFamilies[static_cast<std::size_t>(i) % kFamilies.size()];
  const std::string fb = kFamilies[static_cast<std::size_t>(uniform(rng, 0, long(kFamilies.size()) - 1))];
  DrawnCase c;
  c.a = self_crossing_input(fa, rng);
  c.b = self_crossing_input(fb, rng);
  transform(rng, c.a, c.b);
  c.qa = q_rings(c.a);
  c.qb = q_rings(c.b);
  c.what = "case " + std::to_string(i) + " (" + fa + ", " + fb + "): A " + describe(c.a) + " B " + describe(c.b);
  return c;
}

TEST(FillRuleOracle, EveryRuleAndOperationAgreesWithWindingNumbersAtSamplePoints) {
  const std::uint64_t s = seed();
  const long cases = count_from("MK_FILL_CASES", kDefaultCases);
  std::cout << "seed " << s << " (MK_ORACLE_SEED), " << cases << " inputs (MK_FILL_CASES)" << std::endl;
  Rng rng(s);
  long checked_points = 0, operations = 0;
  for (long i = 0; i < cases; ++i) {
    const auto& [a, b, qa, qb, what] = draw_case(i, rng);
    std::vector<QRing> both = qa;
    both.insert(both.end(), qb.begin(), qb.end());
    for (const Rule rule : kRules) {
      for (const Operation op : kOps) {
        ++operations;
        BooleanOptions o;
        o.op = op;
        o.fill_rule = to_fill_rule(rule);
        o.exact_coordinates = true;
        o.area = false;
        o.kernel = "rational";
        BooleanOutput r, e;
        try {
          r = compute(a, b, o);
          o.kernel = "exact";
          e = compute(a, b, o);
        } catch (const std::exception& ex) {
          FAIL() << what << " " << rule_name(rule) << " " << operation_name(op) << ": " << ex.what();
        }
        ASSERT_EQ(canonical_output(r.output), canonical_output(e.output))
            << what << " " << rule_name(rule) << " " << operation_name(op) << ": exact and rational differ";
        ASSERT_EQ(r.output.rounded_valid.has_value(), true);
        const Region result = region_of_output(r.output);
        for (const QPoint& q : samples_near(both, result, rng, 24)) {
          if (is_on_any_ring(both, q) || is_on_any_ring(result.rings, q)) continue;
          const bool in_a = rule_accepts(rule, winding_number(qa, q));
          const bool in_b = rule_accepts(rule, winding_number(qb, q));
          ++checked_points;
          ASSERT_EQ(face_is_in(result, q), face_in_result(op, in_a, in_b))
              << what << " " << rule_name(rule) << " " << operation_name(op) << " at " << show(q)
              << ": winding numbers " << winding_number(qa, q) << ", " << winding_number(qb, q);
        }
      }
    }
  }
  std::cout << operations << " operations, " << checked_points << " sample points checked" << std::endl;
}

// ---- non-regular results: the closed-set operation of the regions' closures

// At sample points (every vertex, the crossings of A's edges with B's, the midpoints of the
// pieces of input edges, the result's vertices and edge midpoints, random points) the
// non-regular result holds the point exactly when the closed-set operation does, each
// input's closure and interior read from the winding numbers of the open sectors around
// the point (the oracle's neighbourhood: the faces its neighbourhood meets).
TEST(FillRuleOracle, NonRegularAgreesWithTheClosuresAtSamplePoints) {
  const std::uint64_t s = seed() + 1;
  const long cases = count_from("MK_FILL_CASES", kDefaultCases) / 20;
  std::cout << "seed " << s << " (MK_ORACLE_SEED + 1), " << cases << " inputs (MK_FILL_CASES / 20)" << std::endl;
  Rng rng(s);
  long checked = 0, in_lower_dimensional = 0;
  for (long i = 0; i < cases; ++i) {
    const auto& [a, b, qa, qb, what] = draw_case(i, rng);
    const Region ra{qa, false}, rb{qb, false};  // for their rings' directions only
    const std::vector<const Region*> inputs{&ra, &rb};
    for (const Rule rule : kRules) {
      for (const Operation op : kOps) {
        BooleanOptions o;
        o.op = op;
        o.regular = false;
        o.fill_rule = to_fill_rule(rule);
        o.exact_coordinates = true;
        o.area = false;
        o.kernel = "exact";
        BooleanOutput r;
        try {
          r = compute(a, b, o);
        } catch (const std::exception& ex) {
          FAIL() << what << " " << rule_name(rule) << " " << operation_name(op) << ": " << ex.what();
        }
        const Region result = region_of_output(r.output);
        std::vector<QRing> lower_dimensional;  // the result's two- and one-sided parts
        for (const QRing& ring : result.rings) {
          if (ring.size() < 3) lower_dimensional.push_back(ring);
        }
        std::vector<QPoint> samples = sample_points(ra, rb, result, rng, 8);
        std::shuffle(samples.begin(), samples.end(), rng);
        if (samples.size() > 40) samples.resize(40);
        for (const QPoint& p : samples) {
          const Neighbourhood n = neighbourhood(p, inputs);
          bool closure[2] = {false, false}, interior[2] = {true, true};
          for (const QPoint& q : n.sector_points) {
            const bool in[2] = {rule_accepts(rule, winding_number(qa, q)), rule_accepts(rule, winding_number(qb, q))};
            for (int g = 0; g < 2; ++g) {
              closure[g] = closure[g] || in[g];
              interior[g] = interior[g] && in[g];
            }
          }
          const bool expected = in_closed_result(op, closure[0], interior[0], closure[1], interior[1]);
          const Location got = locate(result, p);
          ++checked;
          if (expected && is_on_any_ring(lower_dimensional, p)) ++in_lower_dimensional;
          ASSERT_EQ(got != Location::outside, expected)
              << what << " " << rule_name(rule) << " " << operation_name(op) << " at " << show(p) << ": result "
              << location_name(got);
        }
      }
    }
  }
  std::cout << checked << " sample points checked, " << in_lower_dimensional
            << " of them on the results' two- or one-sided parts" << std::endl;
  EXPECT_GT(in_lower_dimensional, 0);
}

// ---- union-all and intersection-all of valid polygons against CGAL

// A valid polygon on the grid: a rectangle, a right triangle, or a rectangle with a
// rectangular hole, in either direction (union-all orients them itself).
OgcPolygon valid_part(Rng& rng, int grid) {
  OgcPolygon p;
  const long kind = uniform(rng, 0, 2);
  if (kind == 0) {
    p.shell = rectangle(rng, grid);
  } else if (kind == 1) {
    const double x = double(uniform(rng, 0, grid - 2)), y = double(uniform(rng, 0, grid - 2)), s = double(uniform(rng, 1, 2));
    p.shell = {{x, y}, {x + s, y}, {x, y + s}};
  } else {
    const double x = double(uniform(rng, 0, grid - 4)), y = double(uniform(rng, 0, grid - 4));
    p.shell = {{x, y}, {x + 4, y}, {x + 4, y + 4}, {x, y + 4}};
    p.holes.push_back({{x + 1, y + 1}, {x + 1 + double(uniform(rng, 1, 2)), y + 1}, {x + 3, y + 3}, {x + 1, y + 3}});
  }
  maybe_reverse(rng, p.shell);
  for (Ring& h : p.holes) maybe_reverse(rng, h);
  return p;
}

Region region_of_part(const OgcPolygon& p) {
  Polygon poly;
  poly.rings.push_back(p.shell);
  for (const Ring& h : p.holes) poly.rings.push_back(h);
  return region_of(poly);
}

void check_against_cgal(const MultiPolygon& parts, bool intersect, const std::string& what) {
  BooleanOptions o;
  o.kernel = "rational";
  o.exact_coordinates = true;
  o.area_exact = true;
  const BooleanOutput r = intersect ? intersection_all(parts, o) : union_all(parts, o);
  o.kernel = "exact";
  const BooleanOutput e = intersect ? intersection_all(parts, o) : union_all(parts, o);
  ASSERT_EQ(canonical_output(r.output), canonical_output(e.output)) << what << ": exact and rational differ";
  CgalSet all = CgalSet::of(region_of_part(parts[0]));
  for (std::size_t i = 1; i < parts.size(); ++i) {
    all = all.apply(intersect ? Operation::intersection : Operation::union_, CgalSet::of(region_of_part(parts[i])));
  }
  const std::optional<Q> area = all.area();
  ASSERT_TRUE(area.has_value());
  ASSERT_EQ(r.stats.area_exact.value_or("?"), area->get_str()) << what << ": area differs from CGAL's";
  ASSERT_TRUE(CgalSet::of(region_of_output(r.output)).same_as(all)) << what << ": region differs from CGAL's";
}

TEST(FillRuleOracle, UnionAllAndIntersectionAllEqualCgalOnValidParts) {
  const std::uint64_t s = seed();
  const long sets = count_from("MK_FILL_SETS", kDefaultSets);
  std::cout << "seed " << s << " (MK_ORACLE_SEED), " << sets << " sets (MK_FILL_SETS)" << std::endl;
  Rng rng(s);
  for (long i = 0; i < sets; ++i) {
    MultiPolygon parts;
    const int grid = int(uniform(rng, 5, 12));
    for (long k = uniform(rng, 1, 30); k > 0; --k) parts.push_back(valid_part(rng, grid));
    check_against_cgal(parts, false, "union-all set " + std::to_string(i));
    MultiPolygon few(parts.begin(), parts.begin() + std::min<long>(long(parts.size()), uniform(rng, 1, 3)));
    check_against_cgal(few, true, "intersection-all set " + std::to_string(i));
  }
}

// One large set: 1,000 parts on a 40 x 40 grid (shared edges and vertices everywhere).
TEST(FillRuleOracle, UnionAllOfAThousandPartsEqualsCgal) {
  Rng rng(seed() + 1);
  MultiPolygon parts;
#ifdef MK_SANITIZE_BUILD
  const int n = 100;
#else
  const int n = 1000;
#endif
  for (int k = 0; k < n; ++k) {
    OgcPolygon p = valid_part(rng, 40);
    parts.push_back(p);
  }
  check_against_cgal(parts, false, "union-all of " + std::to_string(n) + " parts");
}

}  // namespace
}  // namespace mk::oracle
