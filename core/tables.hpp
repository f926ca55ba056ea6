// The paper's control Tables 1-4, derived from the semantics (BRIEF.md section 1) because
// their bodies are lost from our copy of the text; transcribed cell by cell in paper-notes.md.
// [MK89 Table 1] [MK89 Table 2] [MK89 Table 3] [MK89 Table 4]
// Preconditions: A and B are oriented with FAR on the left of every edge before Table 1.
#pragma once

#include <array>
#include <cstdint>

#include "core/polygon.hpp"

namespace mk {

enum class MutualOrientation : std::uint8_t { same, opposite };

// What to do with an inside or outside fragment [MK89 Table 2].
enum class Keep : std::uint8_t { no, as_is, reversed };

struct FragmentSelection {
  Keep inside;   // fragments inside FAR of the other polygon
  Keep outside;  // fragments outside FAR of the other polygon
};

// Table 2 cell: selection for A's fragments (relative to FAR(B)) and B's (relative to FAR(A)).
struct Table2Cell {
  FragmentSelection a;
  FragmentSelection b;
};

// Table 3 cell: how many copies of a boundary fragment enter EF: 0 (none), 1 (one copy in
// the fragment's direction) or 2 (both directions: a two-sided, dangling result edge).
struct Table3Cell {
  std::uint8_t same;      // boundary-same fragments
  std::uint8_t opposite;  // boundary-opposite fragments
};

constexpr std::size_t op_index(Operation op) { return static_cast<std::size_t>(op); }
constexpr std::size_t type_index(PolygonType t) { return static_cast<std::size_t>(t); }

// Indexed [operation][type of A][type of B]; operations in the order of mk::Operation
// (intersection, union, difference, symmetric difference), types island then hole.
template <class T>
using OpTypeTable = std::array<std::array<std::array<T, 2>, 2>, 4>;

// [MK89 Table 1] Whether B runs the same way as A (both with FAR on the left) or is turned
// against it. After this step the regions that the operation combines lie on consistent
// sides: for intersection, union and xor both regions, for difference A and the closure of
// B's complement.
inline constexpr OpTypeTable<MutualOrientation> kTable1 = {{
    // intersection: (I,I) (I,H) / (H,I) (H,H)
    {{{MutualOrientation::same, MutualOrientation::opposite},
      {MutualOrientation::opposite, MutualOrientation::same}}},
    // union
    {{{MutualOrientation::same, MutualOrientation::opposite},
      {MutualOrientation::opposite, MutualOrientation::same}}},
    // difference
    {{{MutualOrientation::opposite, MutualOrientation::same},
      {MutualOrientation::same, MutualOrientation::opposite}}},
    // symmetric difference
    {{{MutualOrientation::same, MutualOrientation::opposite},
      {MutualOrientation::opposite, MutualOrientation::same}}},
}};

namespace table_detail {
constexpr FragmentSelection in_only{Keep::as_is, Keep::no};
constexpr FragmentSelection out_only{Keep::no, Keep::as_is};
constexpr FragmentSelection in_reversed{Keep::reversed, Keep::as_is};
constexpr FragmentSelection out_reversed{Keep::as_is, Keep::reversed};
}  // namespace table_detail

// [MK89 Table 2] Which inside/outside fragments to select. "Inside" is relative to FAR of
// the other polygon, so a hole-type other polygon swaps inside and outside.
inline constexpr OpTypeTable<Table2Cell> kTable2 = [] {
  using namespace table_detail;
  OpTypeTable<Table2Cell> t{};
  // intersection: fragments inside the other's region
  t[0][0][0] = {in_only, in_only};
  t[0][0][1] = {out_only, in_only};
  t[0][1][0] = {in_only, out_only};
  t[0][1][1] = {out_only, out_only};
  // union: fragments outside the other's region
  t[1][0][0] = {out_only, out_only};
  t[1][0][1] = {in_only, out_only};
  t[1][1][0] = {out_only, in_only};
  t[1][1][1] = {in_only, in_only};
  // difference A - B: A's fragments outside B's region, B's fragments inside A's region
  // (B already turned by Table 1)
  t[2][0][0] = {out_only, in_only};
  t[2][0][1] = {in_only, in_only};
  t[2][1][0] = {out_only, out_only};
  t[2][1][1] = {in_only, out_only};
  // symmetric difference: everything; fragments inside the other's region reversed
  t[3][0][0] = {in_reversed, in_reversed};
  t[3][0][1] = {out_reversed, in_reversed};
  t[3][1][0] = {in_reversed, out_reversed};
  t[3][1][1] = {out_reversed, out_reversed};
  return t;
}();

// [MK89 Table 3] Boundary fragments, indexed [regular][operation][type of A][type of B].
// Same and opposite refer to directions after Table 1.
inline constexpr std::array<OpTypeTable<Table3Cell>, 2> kTable3 = [] {
  std::array<OpTypeTable<Table3Cell>, 2> t{};
  for (int regular = 0; regular < 2; ++regular) {
    for (int ta = 0; ta < 2; ++ta) {
      for (int tb = 0; tb < 2; ++tb) {
        const std::uint8_t dangling = regular ? 0 : 2;
        t[regular][0][ta][tb] = {1, dangling};  // intersection
        t[regular][1][ta][tb] = {1, 0};         // union
        t[regular][2][ta][tb] = {1, dangling};  // difference
        t[regular][3][ta][tb] = {dangling, 0};  // symmetric difference
      }
    }
  }
  return t;
}();

// [MK89 Table 4] The type of a result polygon that runs in A's orientation (with FAR on
// its left, i.e. counterclockwise); a clockwise result polygon has the other type.
inline constexpr OpTypeTable<PolygonType> kTable4 = [] {
  OpTypeTable<PolygonType> t{};
  for (auto& by_op : t) {
    by_op[0][0] = by_op[0][1] = PolygonType::island;
    by_op[1][0] = by_op[1][1] = PolygonType::hole;
  }
  return t;
}();

}  // namespace mk
