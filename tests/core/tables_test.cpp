// Every cell of Tables 1-3 checked against the semantics: for a fragment that bounds its
// own polygon, the paper's table-driven selection must equal what the set operation keeps.
#include <gtest/gtest.h>

#include "core/step5_select.hpp"
#include "core/tables.hpp"

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

// Table 4: a counterclockwise result polygon has the region on its left exactly when A's
// region is on the left of A's counterclockwise parts, i.e. when A is an island.
TEST(Tables, Table4FollowsTheSideOfTheResultRegion) {
  for (const Operation op : kOps) {
    for (const PolygonType ta : kTypes) {
      for (const PolygonType tb : kTypes) {
        EXPECT_EQ(kTable4[op_index(op)][type_index(ta)][type_index(tb)], ta);
      }
    }
  }
}

}  // namespace
}  // namespace mk
