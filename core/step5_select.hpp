// Step 5: select the edge fragments that bound the result and organise them in EF.
// [MK89 §3.1 step 5] [MK89 Table 2] [MK89 Table 3] [MK89 §3.2] (InsertEF; degenerate
// single-point fragments)
// Preconditions: step 4 done. Fragments that bound their own polygon's region on exactly
// one side (the paper's domain of regular parts) are selected by Tables 2 and 3; the others
// (internal double edges, two-sided degenerate parts) by the set operation itself, which
// the tables are a special case of (paper-notes.md, deviations).
#pragma once

#include <array>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/arrangement.hpp"
#include "core/edge_fragment_table.hpp"
#include "core/parallel.hpp"
#include "core/step4_classify.hpp"
#include "core/tables.hpp"

namespace mk {

// [MK89 §3.1 step 4] The four classes of a fragment relative to the other polygon.
enum class FragmentClass : unsigned char { inside, outside, boundary_same, boundary_opposite };

// Whether a face with the given memberships in A's and B's regions is in the result. The
// regular and non-regular operations agree on open faces.
constexpr bool is_face_in_result(Operation op, bool in_a, bool in_b) {
  switch (op) {
    case Operation::intersection: return in_a && in_b;
    case Operation::union_: return in_a || in_b;
    case Operation::difference: return in_a && !in_b;
    case Operation::symmetric_difference: return in_a != in_b;
  }
  return false;
}

// Whether a point (or segment) is in the closed-set result [MK89 §2.3], from its membership
// in the closed sets A and B and in their interiors.
constexpr bool is_in_closed_result(Operation op, bool in_a, bool int_a, bool in_b, bool int_b) {
  switch (op) {
    case Operation::intersection: return in_a && in_b;
    case Operation::union_: return in_a || in_b;
    case Operation::difference: return in_a && !int_b;
    case Operation::symmetric_difference: return (in_a && !int_b) || (in_b && !int_a);
  }
  return false;
}

constexpr bool is_in_region(PolygonType t, int far_depth) { return (far_depth > 0) != (t == PolygonType::hole); }

// What the set operation keeps of one fragment.
enum class Selection : unsigned char { none, as_is, reversed, both };

struct FragmentSides {
  bool a_left, a_right, b_left, b_right;  // region memberships beside the fragment
  bool on_a, on_b;                        // the fragment lies on A's / B's edges
};

// The general rule: keep the fragment where the result lies on exactly one side (oriented so
// that the result is on the side Table 4 expects), and in non-regular output keep both
// directions where the result contains the fragment but neither side.
constexpr Selection select_by_set_operation(Operation op, bool regular, PolygonType type_a, const FragmentSides& s) {
  const bool left = is_face_in_result(op, s.a_left, s.b_left);
  const bool right = is_face_in_result(op, s.a_right, s.b_right);
  const bool result_on_left = type_a == PolygonType::island;
  if (left != right) return left == result_on_left ? Selection::as_is : Selection::reversed;
  if (regular || left) return Selection::none;
  const bool in_a = s.on_a || s.a_left || s.a_right;
  const bool in_b = s.on_b || s.b_left || s.b_right;
  const bool dangling = is_in_closed_result(op, in_a, s.a_left && s.a_right, in_b, s.b_left && s.b_right);
  return dangling ? Selection::both : Selection::none;
}

constexpr Selection selection_of(Keep k) {
  return k == Keep::as_is ? Selection::as_is : (k == Keep::reversed ? Selection::reversed : Selection::none);
}

constexpr Selection selection_of_copies(std::uint8_t copies) {
  return copies == 0 ? Selection::none : (copies == 1 ? Selection::as_is : Selection::both);
}

// The paper's rule [MK89 Tables 2, 3] for a fragment of polygon p (0 = A, 1 = B) in class c.
constexpr Selection select_by_tables(Operation op, bool regular, PolygonType ta, PolygonType tb, int p,
                                     FragmentClass c) {
  const auto& t2 = kTable2[op_index(op)][type_index(ta)][type_index(tb)];
  const auto& sel = p == 0 ? t2.a : t2.b;
  const auto& t3 = kTable3[regular ? 1 : 0][op_index(op)][type_index(ta)][type_index(tb)];
  switch (c) {
    case FragmentClass::inside: return selection_of(sel.inside);
    case FragmentClass::outside: return selection_of(sel.outside);
    case FragmentClass::boundary_same: return selection_of_copies(t3.same);
    case FragmentClass::boundary_opposite: return selection_of_copies(t3.opposite);
  }
  return Selection::none;
}

// The EF entries of fragment f of a polygon, given what step 5 keeps of it: the fragment
// itself, its reverse, or both.
template <class F>
void for_each_entry_of(const PreparedPolygon& poly, const Fragment& f, Selection s, F&& insert) {
  if (s == Selection::none) return;
  const Edge& e = poly.edges[f.edge];
  const Direction dir{e.src, e.dst};
  if (s == Selection::as_is || s == Selection::both) insert(EfEntry{f.from, f.to, dir, true});
  if (s == Selection::reversed || s == Selection::both) insert(EfEntry{f.to, f.from, dir.reversed(), true});
}

// What the result keeps of fragment f of polygon p (0 = A, 1 = B) [MK89 §3.1 step 5].
template <Kernel K>
[[gnu::always_inline]] inline Selection select_fragment(const Arrangement<K>& arr, const Incidence& inc, Operation op,
                                                        bool regular, int p, const Fragment& f) {
  const PolygonType ta = arr.polygon[0].type;
  const PolygonType tb = arr.polygon[1].type;
  const PreparedPolygon& poly = arr.polygon[p];
  const int q = 1 - p;
  const bool own_left = f.far_left[p] > 0;
  const bool own_right = f.far_right[p] > 0;
  const bool other_left = f.far_left[q] > 0;
  const bool other_right = f.far_right[q] > 0;
  const auto [same, opposite] = fragments_along(arr.polygon[q], inc.ends[q], f.from, f.to);
  // A regular part of its own polygon: its FAR on the side Table 1 put it.
  const bool proper_own = poly.far_sign > 0 ? (own_left && !own_right) : (!own_left && own_right);
  const bool proper_other = other_left != other_right ? same + opposite == 1 : same + opposite == 0;
  if (proper_own && proper_other) {
    FragmentClass c = FragmentClass::outside;
    if (other_left != other_right) {
      c = same == 1 ? FragmentClass::boundary_same : FragmentClass::boundary_opposite;
    } else if (other_left) {
      c = FragmentClass::inside;
    }
    return select_by_tables(op, regular, ta, tb, p, c);
  }
  const FragmentSides sides{is_in_region(ta, f.far_left[0]),  is_in_region(ta, f.far_right[0]),
                            is_in_region(tb, f.far_left[1]),  is_in_region(tb, f.far_right[1]),
                            p == 0 || same + opposite > 0, p == 1 || same + opposite > 0};
  return select_by_set_operation(op, regular, ta, sides);
}

// Step 5: decides what the result keeps of every fragment of A, then of B, and calls
// insert(p, EfEntry) (p = 0 for A's fragments, 1 for B's) for the entries that makes,
// fragment by fragment [MK89 §3.1 step 5].
template <Kernel K, class F>
void select_fragments(const Arrangement<K>& arr, const Incidence& inc, Operation op, bool regular, F&& insert) {
  for (int p = 0; p < 2; ++p) {
    const PreparedPolygon& poly = arr.polygon[p];
    for (const Fragment& f : poly.fragments) {
      for_each_entry_of(poly, f, select_fragment(arr, inc, op, regular, p, f), [&](const EfEntry& e) { insert(p, e); });
    }
  }
}

// An entry for EF made by select_runs_into_hash: one fragment (count 0), or a run with its
// inner vertices.
struct EfItem {
  EfEntry entry;
  std::size_t begin = 0, count = 0;
};

inline void insert_item(HashEdgeTable& ef, const EfItem& it) {
  if (it.count == 0) {
    ef.insert(it.entry, true);
  } else {
    ef.insert_run(it.entry, it.begin, it.count);
  }
}

// Cycles of fewer fragments than this (squares of a grid) are decided fragment by fragment:
// their runs are short, and looking for them costs more than it saves.
inline constexpr int kShortCycle = 32;

// Polygon p's part of select_runs_into_hash: its entries to out(EfItem) in order, its runs'
// inner vertices written into ef's room from `at` on; cycles of fewer than `short_cycle`
// fragments fragment by fragment.
template <Kernel K, class Out>
void select_runs_of(const Arrangement<K>& arr, const Incidence& inc, Operation op, int p, HashEdgeTable& ef,
                    std::size_t at, int short_cycle, Out&& out) {
  const PreparedPolygon& poly = arr.polygon[static_cast<std::size_t>(p)];
  const FragmentEndTable& own = inc.ends[static_cast<std::size_t>(p)];
  const FragmentEndTable& other = inc.ends[static_cast<std::size_t>(1 - p)];
  const Fragment* const fragment = poly.fragments.data();
  const Edge* const edges = poly.edges.data();
  const auto dir_of = [&](const Fragment& f) {
    const Edge& e = edges[f.edge];
    return Direction{e.src, e.dst};
  };
  const auto add_single = [&](const Fragment& f, Selection s) {
    for_each_entry_of(poly, f, s, [&](const EfEntry& e) { out(EfItem{e, 0, 0}); });
  };
  const std::vector<int>& starts = poly.cycle_first_fragment;
  for (std::size_t c = 0; c + 1 < starts.size(); ++c) {
    const int first = starts[c];
    const int last = starts[c + 1];
    if (last - first < short_cycle) {
      for (int k = first; k < last; ++k) add_single(fragment[k], select_fragment(arr, inc, op, true, p, fragment[k]));
      continue;
    }
    Selection s = select_fragment(arr, inc, op, true, p, fragment[first]);
    for (int i = first; i < last;) {
      // The run i .. j: while the vertex after j is simple, and the fragment after it is
      // kept the same way and does not close the cycle (each fragment decided once:
      // `after` is j + 1's selection).
      int j = i;
      Selection after = Selection::none;
      bool decided = false;
      const bool can_run = s == Selection::as_is || s == Selection::reversed;
      while (j + 1 < last) {
        const Fragment& g = fragment[j + 1];
        after = select_fragment(arr, inc, op, true, p, g);
        decided = true;
        if (!can_run || after != s || other.reaches(g.from) || !own.is_simple(g.from) || g.to == fragment[i].from) {
          break;
        }
        ++j;
        decided = false;
      }
      if (j == i || (s == Selection::reversed && j == i + 1)) {
        for (int k = i; k <= j; ++k) add_single(fragment[k], s);
      } else if (s == Selection::as_is) {
        const std::size_t begin = at;
        for (int k = i + 1; k <= j; ++k) ef.set_inner(at++, fragment[k].from, dir_of(fragment[k]));
        out(EfItem{EfEntry{fragment[i].from, fragment[j].to, dir_of(fragment[i]), true}, begin, at - begin});
      } else {  // reversed: fragment i alone first, then j down to i + 1 as one run
        add_single(fragment[i], s);
        const std::size_t begin = at;
        for (int k = j - 1; k > i; --k) ef.set_inner(at++, fragment[k].to, dir_of(fragment[k]).reversed());
        out(EfItem{EfEntry{fragment[j].to, fragment[i + 1].from, dir_of(fragment[j]).reversed(), true}, begin,
                   at - begin});
      }
      i = j + 1;
      if (i < last) s = decided ? after : select_fragment(arr, inc, op, true, p, fragment[i]);
    }
  }
}

// Step 5 fragment by fragment into a hash table, in regular output: the same entries in the
// same order as select_fragments makes. On threads the decisions come first, in parts (a
// grid of 10^5 squares: 1.2M fragments, 27 ns each, most of it fetching the other polygon's
// fragment ends), then the insertions, one thread in fragment order.
template <Kernel K>
void select_each_into_hash(const Arrangement<K>& arr, const Incidence& inc, Operation op, HashEdgeTable& ef,
                           unsigned threads = 1) {
  const auto insert = [&](const EfEntry& e) { ef.insert(e, true); };
  const unsigned t = threads_for(arr.polygon[0].fragments.size() + arr.polygon[1].fragments.size(), threads);
  if (t < 2) {
    select_fragments(arr, inc, op, true, [&](int, const EfEntry& e) { insert(e); });
    return;
  }
  std::array<std::vector<Selection>, 2> selection;
  const std::size_t parts = 4 * static_cast<std::size_t>(t);  // per polygon
  for (std::size_t p = 0; p < 2; ++p) selection[p].resize(arr.polygon[p].fragments.size());
  run_tasks(t, 2 * parts, [&](std::size_t task) {
    const int p = static_cast<int>(task / parts);
    const std::size_t part = task % parts;
    const auto& fragments = arr.polygon[static_cast<std::size_t>(p)].fragments;
    const std::size_t n = fragments.size();
    for (std::size_t i = n * part / parts, last = n * (part + 1) / parts; i < last; ++i) {
      selection[static_cast<std::size_t>(p)][i] = select_fragment(arr, inc, op, true, p, fragments[i]);
    }
  });
  for (std::size_t p = 0; p < 2; ++p) {
    const PreparedPolygon& poly = arr.polygon[p];
    for (std::size_t i = 0; i < poly.fragments.size(); ++i) for_each_entry_of(poly, poly.fragments[i], selection[p][i], insert);
  }
}

// Step 5 into a hash table, in regular output: the same entries as select_fragments makes,
// except that a run of consecutive fragments of a cycle kept the same way, whose inner
// vertices no other fragment of either polygon meets, is one entry (HashEdgeTable::
// insert_run). A run kept reversed gives its first fragment an entry of its own, inserted
// before the rest: the first entry in insertion order, where step 6 starts its walks, is
// then the same as fragment by fragment, and so are the cycles and their first vertices.
// The inner vertices of a run have one way in and one way out, so step 6 passes them the
// same way either way. With no long cycle at all (a grid of squares), select_each_into_hash.
// When both polygons have many fragments in long cycles, B's are
// decided on a second thread beside A's, which go into EF as they are decided, and B's
// entries wait until A's are in (each polygon writes its runs' inner vertices into its own
// part of the table's room). `short_cycle`: see kShortCycle (tests take 1, every cycle).
// [MK89 §3.3] (EF) (a deviation: paper-notes.md)
template <Kernel K>
void select_runs_into_hash(const Arrangement<K>& arr, const Incidence& inc, Operation op, HashEdgeTable& ef,
                           unsigned threads = 1, int short_cycle = kShortCycle) {
  std::array<std::size_t, 2> in_long{0, 0};  // fragments in cycles of short_cycle or more
  for (std::size_t p = 0; p < 2; ++p) {
    const std::vector<int>& starts = arr.polygon[p].cycle_first_fragment;
    for (std::size_t c = 0; c + 1 < starts.size(); ++c) {
      if (starts[c + 1] - starts[c] >= short_cycle) in_long[p] += static_cast<std::size_t>(starts[c + 1] - starts[c]);
    }
  }
  if (in_long[0] + in_long[1] == 0) {
    select_each_into_hash(arr, inc, op, ef, threads);
    return;
  }
  ef.make_inner_room(in_long[0] + in_long[1]);
  const auto direct = [&](const EfItem& it) { insert_item(ef, it); };
  if (threads < 2 || std::min(in_long[0], in_long[1]) < kParallelWork) {
    select_runs_of(arr, inc, op, 0, ef, 0, short_cycle, direct);
    select_runs_of(arr, inc, op, 1, ef, in_long[0], short_cycle, direct);
    return;
  }
  std::vector<EfItem> later;  // B's entries
  run_tasks(2, 2, [&](std::size_t p) {
    if (p == 0) {
      select_runs_of(arr, inc, op, 0, ef, 0, short_cycle, direct);
    } else {
      select_runs_of(arr, inc, op, 1, ef, in_long[0], short_cycle, [&](const EfItem& it) { later.push_back(it); });
    }
  });
  for (const EfItem& it : later) insert_item(ef, it);
}

// Isolated points of the non-regular result [MK89 §3.2: degenerate single-point fragments
// are selected only without regularity and only where no other fragment is adjacent]: points
// of the closed-set result with no result face or selected fragment around them.
template <Kernel K>
std::vector<int> select_isolated_points(const Arrangement<K>& arr, const Incidence& inc, Operation op,
                                        const std::vector<bool>& touched) {
  const PolygonType ta = arr.polygon[0].type;
  const PolygonType tb = arr.polygon[1].type;
  std::vector<int> candidates;  // crossings too: two dangling edges may cross at an isolated point
  for (int v = 0; v < arr.num_vertices(); ++v) {
    if (!inc.ends[0].at(v).empty() && !inc.ends[1].at(v).empty()) candidates.push_back(v);
  }
  for (const auto& poly : arr.polygon) {
    for (const int v : poly.point_cycles) candidates.push_back(v);
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  std::array<std::vector<bool>, 2> is_point_cycle;
  for (int p = 0; p < 2; ++p) {
    is_point_cycle[p].assign(static_cast<std::size_t>(arr.num_vertices()), false);
    for (const int v : arr.polygon[p].point_cycles) is_point_cycle[p][v] = true;
  }
  std::vector<int> out;
  for (const int v : candidates) {
    if (touched[v]) continue;
    // The faces around v, as (in A's region, in B's region) pairs.
    bool any_a = false, all_a = true, any_b = false, all_b = true, any_result = false;
    bool has_faces = false;
    for (int p = 0; p < 2; ++p) {
      for (const FragmentEnd& end : inc.ends[p].at(v)) {
        const Fragment& f = arr.polygon[p].fragments[end.fragment()];
        for (int side = 0; side < 2; ++side) {
          const bool in_a = is_in_region(ta, side == 0 ? f.far_left[0] : f.far_right[0]);
          const bool in_b = is_in_region(tb, side == 0 ? f.far_left[1] : f.far_right[1]);
          has_faces = true;
          any_a = any_a || in_a;
          all_a = all_a && in_a;
          any_b = any_b || in_b;
          all_b = all_b && in_b;
          any_result = any_result || is_face_in_result(op, in_a, in_b);
        }
      }
    }
    if (!has_faces) {  // a one-sided polygon away from every edge
      const bool in_a = is_in_region(ta, far_depth_at(arr, 0, v));
      const bool in_b = is_in_region(tb, far_depth_at(arr, 1, v));
      any_a = all_a = in_a;
      any_b = all_b = in_b;
      any_result = is_face_in_result(op, in_a, in_b);
    }
    if (any_result) continue;
    const bool on_a = !inc.ends[0].at(v).empty() || is_point_cycle[0][v];
    const bool on_b = !inc.ends[1].at(v).empty() || is_point_cycle[1][v];
    if (is_in_closed_result(op, on_a || any_a, all_a, on_b || any_b, all_b)) out.push_back(v);
  }
  return out;
}

// Step 5 as the driver calls it: the selected fragments into EF, A's then B's (the sorted
// organisation takes each polygon's entries as one batch, the hash table one entry at a
// time), then, in non-regular output, the isolated points, which are returned.
template <Kernel K, class Table>
std::vector<int> select_into_ef(const Arrangement<K>& arr, const Incidence& inc, Operation op, bool regular,
                                Table& ef, unsigned threads = 1) {
  if constexpr (std::is_same_v<Table, SortedEdgeTable>) {
    std::array<std::vector<EfEntry>, 2> batch;
    select_fragments(arr, inc, op, regular, [&](int p, const EfEntry& e) { batch[p].push_back(e); });
    for (auto& b : batch) ef.insert_batch(std::move(b), regular);
  } else {
    if constexpr (std::is_same_v<Table, HashEdgeTable>) {
      if (regular) {
        select_runs_into_hash(arr, inc, op, ef, threads);
        return {};
      }
    }
    select_fragments(arr, inc, op, regular, [&](int, const EfEntry& e) { ef.insert(e, regular); });
  }
  if (regular) return {};
  std::vector<bool> touched(static_cast<std::size_t>(arr.num_vertices()), false);
  ef.for_each([&](const EfEntry& e) { touched[e.from] = touched[e.to] = true; });
  return select_isolated_points(arr, inc, op, touched);
}

}  // namespace mk
