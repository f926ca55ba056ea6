// Fill rules against CGAL's arrangement: for random self-crossing inputs on a small lattice
// (random crossing rings, bow-ties, star polygons, rings traced twice, overlapping parts with
// holes, figure eights, edges running back along themselves: shared vertices, collinear
// overlaps and vertices on edges by construction), every rule (evenodd, nonzero, positive,
// negative, union) and every operation, mkbool's exact and rational kernels must give the
// region of the arrangement's faces that the rule and operation select: equal exact areas,
// and an empty symmetric difference (CGAL Polygon_set_2). The winding numbers come from
// cgal_winding.hpp, which shares nothing with core/ or with winding.hpp's ray crossings.
// [BRIEF §1, extended by issue 13] [BRIEF §3] (exact kernels agree on every input)
// Preconditions: CGAL 5.5. Environment: MK_ORACLE_SEED (a number, or "random"),
// MK_FILL_CGAL_CASES (random inputs; default 5000 in Release, 250 under the sanitizers).
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "api/mkbool.hpp"
#include "tests/oracle/cgal_reference.hpp"
#include "tests/oracle/cgal_winding.hpp"
#include "tests/oracle/families.hpp"

namespace mk::oracle {
namespace {

#ifdef MK_SANITIZE_BUILD
constexpr long kDefaultCases = 250;
#else
constexpr long kDefaultCases = 5000;
#endif
// Every this many inputs, the regions are also compared by CGAL's Boolean operations.
constexpr long kPolygonSetEvery = 25;

using Rng = std::mt19937_64;
using Clock = std::chrono::steady_clock;

std::uint64_t seed() {
  const char* s = std::getenv("MK_ORACLE_SEED");
  if (s == nullptr || *s == '\0') return 20261125;
  if (std::string(s) == "random") return std::random_device{}();
  return std::strtoull(s, nullptr, 10);
}

long case_count() {
  const char* s = std::getenv("MK_FILL_CGAL_CASES");
  return s == nullptr || *s == '\0' ? kDefaultCases : std::strtol(s, nullptr, 10);
}

long uniform(Rng& rng, long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); }
bool chance(Rng& rng, int one_in) { return uniform(rng, 0, one_in - 1) == 0; }
Point at(long x, long y) { return {double(x), double(y)}; }

// ---- self-crossing inputs on the lattice [0, 8]^2 (the harness's generators have the same
// names: experiments/generators_fill.cpp)

Ring random_ring(Rng& rng, int grid, int n) {
  Ring r;
  for (int i = 0; i < n; ++i) r.push_back(at(uniform(rng, 0, grid), uniform(rng, 0, grid)));
  return r;
}

Ring rectangle(Rng& rng, int grid) {
  const long x0 = uniform(rng, 0, grid - 1), y0 = uniform(rng, 0, grid - 1);
  const long x1 = uniform(rng, x0 + 1, grid), y1 = uniform(rng, y0 + 1, grid);
  return {at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y1)};
}

// Crossing at the lattice point (x + s, y + s), so other rings can pass through it.
Ring bowtie(Rng& rng) {
  const long x = uniform(rng, 0, 4), y = uniform(rng, 0, 4), s = uniform(rng, 1, 2);
  return {at(x, y), at(x + 2 * s, y + 2 * s), at(x + 2 * s, y), at(x, y + 2 * s)};
}

// {5/2}, {7/3} and {7/2} star polygons on lattice points (centres wound 2 or 3 times).
Ring pentagram(Rng& rng) {
  static const std::vector<std::vector<std::array<long, 2>>> stars{
      {{4, 0}, {6, 6}, {8, 0}, {3, 4}, {9, 4}},
      {{5, 0}, {2, 7}, {8, 6}, {1, 2}, {9, 2}, {2, 6}, {8, 7}},
      {{4, 0}, {8, 5}, {1, 7}, {2, 1}, {8, 2}, {3, 8}, {0, 4}}};
  const auto& s = stars[static_cast<std::size_t>(uniform(rng, 0, 2))];
  const long dx = uniform(rng, -2, 0), dy = uniform(rng, -2, 0);
  Ring r;
  for (const auto& p : s) r.push_back(at(p[0] + dx, p[1] + dy));
  return r;
}

void shuffle_ring(Rng& rng, Ring& r) {
  if (chance(rng, 2)) std::reverse(r.begin(), r.end());
  std::rotate(r.begin(), r.begin() + uniform(rng, 0, long(r.size()) - 1), r.end());
}

const std::vector<std::string> kFamilies = {"self_crossing_random", "bowtie_degenerate", "pentagram",
                                            "traced_twice",         "overlapping_multipart", "figure_eight",
                                            "collinear_spikes"};

// A multipolygon whose parts are read by the `union` rule as shells and holes; the other
// rules read all its rings as given.
MultiPolygon self_crossing_input(const std::string& family, Rng& rng) {
  MultiPolygon mp;
  const auto part = [&](Ring shell) -> OgcPolygon& { return mp.emplace_back(OgcPolygon{std::move(shell), {}}); };
  if (family == "self_crossing_random") {
    for (long k = uniform(rng, 1, 2); k > 0; --k) part(random_ring(rng, int(uniform(rng, 4, 8)), int(uniform(rng, 4, 9))));
    if (chance(rng, 3)) mp[0].holes.push_back(random_ring(rng, 6, int(uniform(rng, 3, 5))));
  } else if (family == "bowtie_degenerate") {  // bow-ties sharing vertices and crossing points
    for (long k = uniform(rng, 1, 3); k > 0; --k) part(bowtie(rng));
  } else if (family == "pentagram") {
    part(pentagram(rng));
    if (chance(rng, 3)) part(rectangle(rng, 8));
  } else if (family == "traced_twice") {  // winding 2, or 3 or 1 with the ring again either way
    Ring r = chance(rng, 2) ? rectangle(rng, 8) : random_ring(rng, 8, 4);
    Ring twice = r;
    twice.insert(twice.end(), r.begin(), r.end());
    part(twice);
    if (chance(rng, 2)) part(chance(rng, 2) ? r : Ring(r.rbegin(), r.rend()));
  } else if (family == "overlapping_multipart") {  // shells sharing edges, some with holes
    for (long k = uniform(rng, 2, 4); k > 0; --k) {
      OgcPolygon& p = part(chance(rng, 3) ? random_ring(rng, 8, 3) : rectangle(rng, 8));
      if (chance(rng, 3)) p.holes.push_back(rectangle(rng, 8));
    }
  } else if (family == "figure_eight") {  // a ring through one vertex twice, loops either way
    const long c = uniform(rng, 2, 4);
    part({at(0, 0), at(c, 0), at(c, c), at(2 * c, c), at(2 * c, 2 * c), at(c, 2 * c), at(c, c), at(0, c)});
  } else {  // collinear_spikes: edges running back along themselves over other edges
    part({at(0, 0), at(4, 0), at(2, 0), at(2, 3), at(0, 3)});
    part(rectangle(rng, 5));
  }
  for (OgcPolygon& p : mp) {
    shuffle_ring(rng, p.shell);
    for (Ring& h : p.holes) shuffle_ring(rng, h);
  }
  return mp;
}

// The frame: an exact rotation by the Pythagorean angle (3, 4, 5) (times 5) and a shift of
// B, integer coordinates that CGAL takes as they are; mkbool takes them scaled by 2^k.
struct Frame {
  bool rotate = false;
  long dx = 0, dy = 0;
  int k = 0;
};

void move(MultiPolygon& mp, const Frame& f, bool shift) {
  const auto map = [&](Ring& r) {
    for (Point& q : r) {
      Point t = f.rotate ? Point{3 * q.x - 4 * q.y, 4 * q.x + 3 * q.y} : q;
      if (shift) t = {t.x + double(f.dx), t.y + double(f.dy)};
      q = t;
    }
  };
  for (OgcPolygon& p : mp) {
    map(p.shell);
    for (Ring& h : p.holes) map(h);
  }
}

Polygon scaled(Polygon p, int k) {
  for (Ring& r : p.rings) {
    for (Point& q : r) q = {std::ldexp(q.x, k), std::ldexp(q.y, k)};
  }
  return p;
}

QRing q_ring(const Ring& r) {
  QRing q;
  for (const Point& v : r) q.push_back({Q(v.x), Q(v.y)});
  return q;
}

// 2^k as a rational.
Q power_of_two(int k) {
  Q p = 1;
  if (k >= 0) mpz_mul_2exp(p.get_num_mpz_t(), p.get_num_mpz_t(), static_cast<mp_bitcnt_t>(k));
  else mpz_mul_2exp(p.get_den_mpz_t(), p.get_den_mpz_t(), static_cast<mp_bitcnt_t>(-k));
  return p;
}

// mkbool's result (regular part) in the frame's coordinates.
Region frame_region(const Output& o, const Q& unscale) {
  Region r;
  r.complement = o.unbounded;
  for (const auto& c : o.irreducible) {
    if (c.vertices.size() < 3) continue;
    QRing ring;
    for (std::size_t i = 0; i < c.vertices.size(); ++i) {
      ring.push_back({Q(c.exact[2 * i]) * unscale, Q(c.exact[2 * i + 1]) * unscale});
    }
    r.rings.push_back(std::move(ring));
  }
  return r;
}

// The rules by their definitions (Clipper's meanings; `union` reads the rings oriented
// shells counterclockwise, holes clockwise, as nonzero), written here from the issue; the
// operations on open faces are membership.hpp's face_in_result.
bool accepts(FillRule rule, int w) {
  switch (rule) {
    case FillRule::evenodd: return w % 2 != 0;
    case FillRule::nonzero:
    case FillRule::union_: return w != 0;
    case FillRule::positive: return w > 0;
    case FillRule::negative: return w < 0;
  }
  return false;
}

constexpr Operation kOps[] = {Operation::intersection, Operation::union_, Operation::difference,
                              Operation::symmetric_difference};
constexpr FillRule kRules[] = {FillRule::evenodd, FillRule::nonzero, FillRule::positive, FillRule::negative,
                               FillRule::union_};

// One operand's rings as the arrangement's operands (one per ring, so that the `union`
// rule can turn a ring around by negating its winding number), and each ring's sign under
// the `union` rule: -1 when the rule reverses it (a shell clockwise, a hole
// counterclockwise; zero signed area: as given).
struct Rings {
  std::vector<QRing> rings;
  std::vector<int> union_sign;
};

Rings rings_of(const MultiPolygon& mp) {
  Rings out;
  const auto add = [&](const Ring& r, int wanted) {
    out.rings.push_back(q_ring(r));
    const int s = orientation_sign(out.rings.back());
    out.union_sign.push_back(s == 0 || s == wanted ? 1 : -1);
  };
  for (const OgcPolygon& p : mp) {
    add(p.shell, 1);
    for (const Ring& h : p.holes) add(h, -1);
  }
  return out;
}

TEST(FillRuleCgalArrangementOracle, EveryRuleAndOperationGivesTheSelectedFacesExactly) {
  const std::uint64_t s = seed();
  const long cases = case_count();
  std::cout << "seed " << s << " (MK_ORACLE_SEED), " << cases << " inputs (MK_FILL_CGAL_CASES)" << std::endl;
  Rng rng(s);
  long operations = 0, nonempty = 0, faces = 0, by_polygon_set = 0;
  std::chrono::duration<double> mkbool_time{0}, reference_time{0}, arrangement_time{0};
  for (long i = 0; i < cases; ++i) {
    const std::string fa = kFamilies[static_cast<std::size_t>(i) % kFamilies.size()];
    const std::string fb = kFamilies[static_cast<std::size_t>(uniform(rng, 0, long(kFamilies.size()) - 1))];
    MultiPolygon a = self_crossing_input(fa, rng), b = self_crossing_input(fb, rng);
    Frame frame{chance(rng, 3), uniform(rng, -3, 3), uniform(rng, -3, 3), chance(rng, 2) ? 0 : int(uniform(rng, -600, 600))};
    move(a, frame, false);
    move(b, frame, true);
    const Rings ra = rings_of(a), rb = rings_of(b);
    std::vector<std::vector<QRing>> operands;
    for (const Rings* r : {&ra, &rb}) {
      for (const QRing& q : r->rings) operands.push_back({q});
    }
    auto t0 = Clock::now();
    const WindingArrangement arr(operands);
    arrangement_time += Clock::now() - t0;
    const std::string what = "case " + std::to_string(i) + " (" + fa + ", " + fb + ", 2^" + std::to_string(frame.k) +
                             "): A " + describe(to_polygon(a)) + " B " + describe(to_polygon(b));
    ASSERT_EQ(arr.inconsistency(), "") << what;
    faces += long(arr.face_count());
    const Q area_scale = power_of_two(2 * frame.k), unscale = power_of_two(-frame.k);
    std::map<WindingArrangement::Selection, CgalSet> references;
    for (const FillRule rule : kRules) {
      const bool by_union = rule == FillRule::union_;
      const Polygon pa = scaled(by_union ? fill_rule_polygon(a, rule) : to_polygon(a), frame.k);
      const Polygon pb = scaled(by_union ? fill_rule_polygon(b, rule) : to_polygon(b), frame.k);
      const auto winding = [&](const std::vector<int>& w, const Rings& r, std::size_t first) {
        int sum = 0;
        for (std::size_t j = 0; j < r.rings.size(); ++j) sum += (by_union ? r.union_sign[j] : 1) * w[first + j];
        return sum;
      };
      for (const Operation op : kOps) {
        ++operations;
        const auto selection = arr.select([&](const std::vector<int>& w) {
          return face_in_result(op, accepts(rule, winding(w, ra, 0)), accepts(rule, winding(w, rb, ra.rings.size())));
        });
        // The two exact kernels take turns (fill_test.cpp checks that they agree): each
        // meets every family, rule and operation.
        BooleanOptions o;
        o.op = op;
        o.fill_rule = rule;
        o.kernel = (i + long(operations)) % 2 == 0 ? "exact" : "rational";
        o.exact_coordinates = true;
        o.area = false;
        o.area_exact = true;
        o.rounding = RoundingMode::nearest;  // the exact result is compared, not its doubles
        const std::string at = what + " " + std::string(fill_rule_name(rule)) + " " + std::string(operation_name(op)) +
                               " (" + o.kernel + ")";
        BooleanOutput r;
        t0 = Clock::now();
        try {
          r = compute(pa, pb, o);
        } catch (const std::exception& ex) {
          FAIL() << at << ": " << ex.what();
        }
        mkbool_time += Clock::now() - t0;
        t0 = Clock::now();
        ASSERT_FALSE(r.output.unbounded) << at;
        const Q area = arr.area(selection);
        if (area != 0) ++nonempty;
        ASSERT_EQ(r.stats.area_exact.value_or("?"), Q(area * area_scale).get_str())
            << at << ": area differs from the arrangement's selected faces (" << area.get_str() << " in the frame)";
        // Equal oriented boundaries (the result on their left) mean equal regions: a region's
        // indicator is the winding number of its boundary. So the symmetric difference is
        // empty exactly when the chains cancel.
        const Region result = frame_region(r.output, unscale);
        const std::string difference = chain_difference(arr.boundary(selection), result.rings);
        ASSERT_EQ(difference, "") << at << ": boundary differs from the selected faces' boundary";
        if (i % kPolygonSetEvery == 0) {  // and, on some cases, by CGAL's own Boolean operations
          auto ref = references.find(selection);
          if (ref == references.end()) ref = references.emplace(selection, CgalSet::of(arr.region(selection))).first;
          ASSERT_TRUE(CgalSet::of(result).same_as(ref->second))
              << at << ": region differs from the arrangement's selected faces (Polygon_set_2)";
          ++by_polygon_set;
        }
        reference_time += Clock::now() - t0;
      }
    }
  }
  std::cout << operations << " operations, " << nonempty << " with nonempty results, " << by_polygon_set
            << " also compared by Polygon_set_2, " << faces << " bounded faces; " << mkbool_time.count() << " s in mkbool, " << arrangement_time.count()
            << " s building arrangements, " << reference_time.count() << " s comparing" << std::endl;
}

// The reference itself on hand-derived cases: winding numbers and areas worked out on paper.
TEST(FillRuleCgalArrangementOracle, ReferenceGivesHandDerivedWindingsAndAreas) {
  const auto q = [](std::initializer_list<std::array<long, 2>> pts) {
    QRing r;
    for (const auto& p : pts) r.push_back({Q(p[0]), Q(p[1])});
    return r;
  };
  // The pentagram {5/2} through (4,0) (6,6) (8,0) (3,4) (9,4): counterclockwise tips (1)
  // around a pentagon wound twice.
  const WindingArrangement star({{q({{4, 0}, {6, 6}, {8, 0}, {3, 4}, {9, 4}})}});
  ASSERT_EQ(star.inconsistency(), "");
  ASSERT_EQ(star.face_count(), 6u);
  int ones = 0, twos = 0;
  for (std::size_t f = 0; f < star.face_count(); ++f) {
    const int w = std::abs(star.windings(f)[0]);
    ones += w == 1;
    twos += w == 2;
  }
  EXPECT_EQ(ones, 5);
  EXPECT_EQ(twos, 1);
  // A unit square traced twice counterclockwise and once clockwise by another operand.
  const QRing square = q({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  QRing twice = square;
  twice.insert(twice.end(), square.begin(), square.end());
  const WindingArrangement traced({{twice}, {QRing(square.rbegin(), square.rend())}});
  ASSERT_EQ(traced.inconsistency(), "");
  ASSERT_EQ(traced.face_count(), 1u);
  EXPECT_EQ(traced.windings(0), (std::vector<int>{2, -1}));
  EXPECT_EQ(traced.area(traced.select([](const std::vector<int>& w) { return w[0] % 2 != 0; })), 0);
  EXPECT_EQ(traced.area(traced.select([](const std::vector<int>& w) { return w[0] != 0; })), 4);
  // A bow-tie (0,0) (2,2) (2,0) (0,2): two triangles of area 1 wound -1 and +1.
  const WindingArrangement bowtie({{q({{0, 0}, {2, 2}, {2, 0}, {0, 2}})}});
  ASSERT_EQ(bowtie.face_count(), 2u);
  EXPECT_EQ(bowtie.area(bowtie.select([](const std::vector<int>& w) { return w[0] > 0; })), 1);
  EXPECT_EQ(bowtie.area(bowtie.select([](const std::vector<int>& w) { return w[0] < 0; })), 1);
  // Chains: the square's boundary equals the square with a redundant vertex and the square
  // as two triangles (their shared diagonal cancels), not the square reversed or shifted.
  const auto b = traced.boundary(traced.select([](const std::vector<int>&) { return true; }));
  EXPECT_EQ(chain_difference(b, {q({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}})}), "");
  EXPECT_EQ(chain_difference(b, {q({{0, 0}, {2, 0}, {2, 2}}), q({{0, 0}, {2, 2}, {0, 2}})}), "");
  EXPECT_NE(chain_difference(b, {QRing(square.rbegin(), square.rend())}), "");
  EXPECT_NE(chain_difference(b, {q({{0, 0}, {2, 0}, {2, 3}, {0, 3}})}), "");
}

}  // namespace
}  // namespace mk::oracle
