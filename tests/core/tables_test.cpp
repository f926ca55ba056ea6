// Every cell of Tables 1-3 checked against the core's general selection rule: for a
// fragment that bounds its own polygon, the paper's table-driven selection must equal what
// the set operation keeps. Table 4 checked against results by the membership oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/shoelace.hpp"
#include "core/boolean_op.hpp"
#include "core/step5_select.hpp"
#include "core/tables.hpp"
#include "oracle.hpp"
#include "tests/oracle/families.hpp"

namespace mk {
namespace {

constexpr Operation kOps[] = {Operation::intersection, Operation::union_, Operation::difference,
                              Operation::symmetric_difference};
constexpr PolygonType kTypes[] = {PolygonType::island, PolygonType::hole};
constexpr FragmentClass kClasses[] = {FragmentClass::inside, FragmentClass::outside, FragmentClass::boundary_same,
                                      FragmentClass::boundary_opposite};

// FAR sides (left, right) of the other polygon beside a fragment, by class, given whether
// the other polygon's fragments run with FAR on their left (far_sign > 0).
std::pair<int, int> other_far(FragmentClass c, int other_far_sign) {
  switch (c) {
    case FragmentClass::inside: return {1, 1};
    case FragmentClass::outside: return {0, 0};
    case FragmentClass::boundary_same: return other_far_sign > 0 ? std::pair{1, 0} : std::pair{0, 1};
    case FragmentClass::boundary_opposite: return other_far_sign > 0 ? std::pair{0, 1} : std::pair{1, 0};
  }
  return {0, 0};
}

TEST(Tables, EveryCellOfTables1To3AgreesWithTheSetOperation) {
  int cells = 0;
  for (const Operation op : kOps) {
    for (const PolygonType ta : kTypes) {
      for (const PolygonType tb : kTypes) {
        const bool turned = kTable1[op_index(op)][type_index(ta)][type_index(tb)] == MutualOrientation::opposite;
        const int far_sign[2] = {1, turned ? -1 : 1};
        for (const bool regular : {true, false}) {
          for (int p = 0; p < 2; ++p) {
            for (const FragmentClass c : kClasses) {
              const int q = 1 - p;
              std::array<std::pair<int, int>, 2> far{};
              far[p] = far_sign[p] > 0 ? std::pair{1, 0} : std::pair{0, 1};
              far[q] = other_far(c, far_sign[q]);
              const bool boundary = c == FragmentClass::boundary_same || c == FragmentClass::boundary_opposite;
              const FragmentSides sides{is_in_region(ta, far[0].first), is_in_region(ta, far[0].second),
                                        is_in_region(tb, far[1].first), is_in_region(tb, far[1].second),
                                        p == 0 || boundary, p == 1 || boundary};
              const Selection by_rule = select_by_set_operation(op, regular, ta, sides);
              const Selection by_tables = select_by_tables(op, regular, ta, tb, p, c);
              EXPECT_EQ(static_cast<int>(by_tables), static_cast<int>(by_rule))
                  << operation_name(op) << " A " << int(ta) << " B " << int(tb) << " regular " << regular
                  << " fragment of " << (p == 0 ? "A" : "B") << " class " << int(c);
              ++cells;
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(cells, 4 * 2 * 2 * 2 * 2 * 4);
}

// A square ring, with sides a power of two, around every point of x and y.
void add_enclosing_box(Polygon& to, const Polygon& x, const Polygon& y) {
  double largest = 1;
  for (const Polygon* p : {&x, &y}) {
    for (const auto& r : p->rings) {
      for (const auto& v : r) largest = std::max({largest, std::abs(v.x), std::abs(v.y)});
    }
  }
  const double s = std::ldexp(1.0, std::min(std::ilogb(largest) + 2, 1023));
  to.rings.push_back({{-s, -s}, {s, -s}, {s, s}, {-s, s}});
}

// Table 4 against results: a result polygon is an island exactly when the result region
// lies inside it, which the membership oracle decides just left of one of its edges (inside
// a counterclockwise cycle, outside a clockwise one). Every cell must be met by a
// counterclockwise result polygon of some generated pair, and agree with it.
TEST(Tables, Table4GivesTheTypeTheResultRegionGivesEveryCounterclockwisePolygon) {
  const std::uint64_t seed = 4040;
  std::cout << "seed " << seed << "\n";
  std::array<int, 4 * 2 * 2> met{};
  int cycles = 0;
  for (std::size_t index = 0; index < 8 * oracle::family_names().size(); ++index) {
    std::mt19937_64 rng(seed + index);
    oracle::GeneratedPair pair = oracle::random_pair(index, rng);
    // Nesting, which result holes need: a box around everything added to A or B (by parity
    // it turns that polygon's region inside out within the box).
    if (index % 3 != 0) add_enclosing_box(index % 3 == 1 ? pair.a : pair.b, pair.a, pair.b);
    for (const PolygonType ta : kTypes) {
      for (const PolygonType tb : kTypes) {
        pair.a.type = ta;
        pair.b.type = tb;
        for (const Operation op : kOps) {
          const auto r = boolean_op<RationalKernel>(pair.a, pair.b, Options{op, true});
          const oracle::Region result = oracle::region_of(test::as_input(r));
          for (std::size_t i = 0; i < r.cycles.size(); ++i) {
            const auto& ring = result.rings[i];
            if (ring.size() < 3) continue;
            const bool ccw = twice_signed_area<mpq_class>(ring) > 0;
            const bool region_left = oracle::face_is_in(result, oracle::point_left_of(ring[0], ring[1], {&result}));
            const PolygonType type = ccw == region_left ? PolygonType::island : PolygonType::hole;
            EXPECT_EQ(r.cycles[i].type, type) << operation_name(op) << " pair " << index;
            if (!ccw) continue;
            EXPECT_EQ(kTable4[op_index(op)][type_index(ta)][type_index(tb)], type)
                << operation_name(op) << " A " << int(ta) << " B " << int(tb);
            ++met[op_index(op) * 4 + type_index(ta) * 2 + type_index(tb)];
            ++cycles;
          }
        }
      }
    }
  }
  std::cout << cycles << " counterclockwise result polygons\n";
  for (int cell = 0; cell < 16; ++cell) EXPECT_GT(met[cell], 0) << "cell " << cell << " never met";
}

}  // namespace
}  // namespace mk
