// Step 6: construct the result polygons from EF and find their types.
// [MK89 §3.1 step 6] [MK89 Table 4] [MK89 §4.1, Theorem 2] (every maximal sequence of
// selected fragments decomposes into edge-disjoint cycles)
// Preconditions: EF filled by step 5. Cycles are traced so that the result region stays on
// one side: at a vertex with several selected fragments the walk takes the first one
// turning towards the region, so cycles touch but never cross at shared vertices.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "core/arrangement.hpp"
#include "core/edge_fragment_table.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/tables.hpp"
#include "predicates/directions.hpp"

namespace mk {

// One irreducible result polygon [MK89 §2.2]: a simple cycle (3+ vertices), a two-sided
// segment (2) or a one-sided point (1), as vertex ids of the arrangement.
struct ResultCycle {
  std::vector<int> vertices;
  std::vector<Direction> directions;  // direction of travel of each edge (empty for points)
  PolygonType type = PolygonType::island;
  bool counterclockwise = true;  // meaningful for 3+ vertices
};

namespace detail {

// The turning number of a closed sequence of directions: +1 counterclockwise, -1 clockwise.
// With exact predicates, a turn wraps past east only between directions in different halves
// (DirectionOrder::is_upper): within one half, compare(b, a) is -orient(b, a), the turn
// itself, so wraps() is 0 there, and one half test per direction replaces most orientations.
// Rounded predicates need not be antisymmetric: they take wraps() at every turn.
// The turns after directions [first, last) of the n = dirs.size() (each with the next one,
// the last with the first), a sum that parts of a long cycle make apart.
template <Kernel K>
int turns_after(const DirectionOrder<K>& order, const std::vector<Direction>& dirs, std::size_t first, std::size_t last) {
  int turns = 0;
  const std::size_t n = dirs.size();
  if (first >= last) return 0;
  [[maybe_unused]] bool upper = K::is_exact && order.is_upper(dirs[first]);
  for (std::size_t i = first; i < last; ++i) {
    const std::size_t next = i + 1 < n ? i + 1 : 0;
    if constexpr (K::is_exact) {
      const bool next_upper = order.is_upper(dirs[next]);
      if (next_upper != upper) turns += order.wraps(dirs[i], dirs[next]);
      upper = next_upper;
    } else {
      turns += order.wraps(dirs[i], dirs[next]);
    }
  }
  return turns;
}

// The turning number of the whole sequence, a long one in parts on up to `threads` threads
// (the same sum on any number: each part's turns are its own).
template <Kernel K>
int turning_number(const DirectionOrder<K>& order, const std::vector<Direction>& dirs, unsigned threads = 1) {
  const std::size_t n = dirs.size();
  const unsigned t = threads_for(n / 4, threads);
  if (t < 2) return turns_after(order, dirs, 0, n);
  const std::size_t parts = 4 * static_cast<std::size_t>(t);
  std::vector<int> turns(parts, 0);
  run_tasks(t, parts, [&](std::size_t i) { turns[i] = turns_after(order, dirs, n * i / parts, n * (i + 1) / parts); });
  int sum = 0;
  for (const int k : turns) sum += k;
  return sum;
}

// A traced cycle's orientation and type from its turning number (3+ vertices).
template <Kernel K>
void set_orientation(ResultCycle& cycle, int turns, PolygonType ccw_type) {
  if (turns != 1 && turns != -1) {
    throw KernelFailure(std::string("kernel ") + std::string(K::name) +
                        ": a result cycle is not a simple polygon (turning number " + std::to_string(turns) + ")");
  }
  cycle.counterclockwise = turns == 1;
  cycle.type = cycle.counterclockwise ? ccw_type : opposite(ccw_type);
}

// Step 6 when no walk has a choice: every live entry of EF leads to a vertex that exactly
// one live entry leaves, and no two lead to the same. The walks of construct_result_cycles
// are then the cycles of that successor map whatever order they are made in, each from its
// first entry in insertion order, where the walk starts it. So the successors are found on
// the threads, the cycles traced in one pass on one thread (their order), and each cycle's
// vertices copied out and its turning number found on the threads: the same cycles, in the
// same order, as the walk makes (a grid of 10^5 squares: 10^5 cycles of 4). False, with
// `out` empty and EF untouched, when some vertex has a choice or none: the walk then
// decides, or reports the failure. A cycle from a run of EF gets its inner vertices.
template <Kernel K>
bool forced_cycles(const DirectionOrder<K>& order, const HashEdgeTable& ef, PolygonType ccw_type, unsigned threads,
                   std::vector<ResultCycle>& out) {
  const std::size_t n = ef.size();
  const auto at = [](int i) { return static_cast<std::size_t>(i); };
  std::vector<int> next(n);  // per live entry: the live entry after it; -1 for dead ones
  std::atomic<bool> forced{true};
  run_blocks(threads, n, 8 * static_cast<std::size_t>(threads), [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last && forced.load(std::memory_order_relaxed); ++i) {  // stops at a choice
      const EfEntry& e = ef.entry(i);
      next[i] = e.alive ? ef.only_from(e.to) : -1;
      if (e.alive && (next[i] < 0 || e.from == e.to)) forced = false;
    }
  });
  if (!forced) return false;
  struct Traced {
    int first;             // its first entry in insertion order
    std::size_t vertices;  // with the runs' inner vertices
  };
  std::vector<Traced> traced;
  {
    std::vector<std::uint8_t> seen(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (next[i] < 0 || seen[i]) continue;
      std::size_t vertices = 0;
      std::size_t j = i;
      do {
        seen[j] = 1;
        vertices += 1 + ef.inner_range(ef.entry(j)).second;
        j = at(next[j]);
      } while (j != i && !seen[j]);
      if (j != i) return false;  // two entries lead to one vertex: a walk does not close there
      traced.push_back({static_cast<int>(i), vertices});
    }
  }
  std::vector<ResultCycle> cycles(traced.size());
  std::vector<int> turns(traced.size(), 0);
  const auto is_long = [&](std::size_t c) { return traced[c].vertices >= kParallelWork; };
  run_blocks(threads, traced.size(), 8 * static_cast<std::size_t>(threads), [&](std::size_t first, std::size_t last) {
    for (std::size_t c = first; c < last; ++c) {
      ResultCycle& cycle = cycles[c];
      cycle.vertices.reserve(traced[c].vertices);
      cycle.directions.reserve(traced[c].vertices);
      const std::size_t start = at(traced[c].first);
      std::size_t j = start;
      do {
        const EfEntry& e = ef.entry(j);
        cycle.vertices.push_back(e.from);
        cycle.directions.push_back(e.dir);
        const auto [inner, count] = ef.inner_range(e);
        ef.append_inner(inner, count, cycle.vertices, cycle.directions);
        j = at(next[j]);
      } while (j != start);
      if (cycle.vertices.size() >= 3 && !is_long(c)) turns[c] = turns_after(order, cycle.directions, 0, cycle.directions.size());
    }
  });
  // In order, as the walk would meet them: a long cycle's turns on the threads, and the
  // first cycle that is not simple reported.
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    if (cycles[c].vertices.size() < 3) continue;
    if (is_long(c)) turns[c] = turning_number(order, cycles[c].directions, threads);
    set_orientation<K>(cycles[c], turns[c], ccw_type);
  }
  out = std::move(cycles);
  return true;
}

// The choices of step 6 at vertices with long chains in EF (a fan's apex, where thousands
// of result cycles meet): scanning every entry at each of the thousands of visits would cost
// the square of the degree. At its first visit a vertex's live entries are sorted by angle
// (ties in chain order); later visits find the entry the scan would choose by binary search
// and skip the entries that have died since (a union-find of dead runs each way; entries
// only die). Exact kernels only: a sort by an inconsistent order is undefined.
template <Kernel K>
class AngularChoices {
 public:
  AngularChoices(const DirectionOrder<K>& order, HashEdgeTable& ef, bool result_on_left)
      : order_(&order), ef_(&ef), result_on_left_(result_on_left) {}

  // The live entry from v that the scan of construct_result_cycles chooses after arriving
  // along the reverse of `back`, or nullptr when none is left.
  EfEntry* choose(int v, Direction back) {
    auto [it, made] = at_.try_emplace(v);
    Sorted& s = it->second;
    if (made) make(v, s);
    const int n = static_cast<int>(s.entries.size());
    const bool back_upper = order_->is_upper(back);
    const auto count_below = [&](bool or_equal) {
      const auto at = std::partition_point(s.entries.begin(), s.entries.end(), [&](const Item& item) {
        const Sign c = order_->compare_known(item.entry->dir, item.upper, back, back_upper);
        return c == Sign::negative || (or_equal && c == Sign::zero);
      });
      return static_cast<int>(at - s.entries.begin());
    };
    const int below = count_below(false);
    const int not_above = count_below(true);
    if (const int i = s.alive_from(below); i < not_above) return s.entries[static_cast<std::size_t>(i)].entry;  // two-sided
    int i = -1;
    if (result_on_left_) {  // the first met turning clockwise from `back`
      i = s.alive_until(below - 1);
      if (i < 0) i = s.alive_until(n - 1);
    } else {  // counterclockwise
      i = s.alive_from(not_above);
      if (i >= n) i = s.alive_from(0);
    }
    return i < 0 || i >= n ? nullptr : s.entries[static_cast<std::size_t>(i)].entry;
  }

 private:
  struct Item {
    EfEntry* entry;
    bool upper;  // is_upper of its direction
  };
  struct Sorted {
    std::vector<Item> entries;
    std::vector<int> right;  // for a dead entry: a later index no entry between is alive; else itself
    std::vector<int> left;   // the same, earlier
    // The first live entry at index i or after (n when none), and the last at i or before
    // (-1 when none), shortening the paths over dead entries as it goes.
    int alive_from(int i) { return skip(right, i, +1); }
    int alive_until(int i) { return skip(left, i, -1); }
    int skip(std::vector<int>& link, int i, int step) {
      const int n = static_cast<int>(entries.size());
      const auto out = [&](int j) { return j < 0 || j >= n; };
      int root = i;
      while (!out(root) && !entries[static_cast<std::size_t>(root)].entry->alive) {
        const int l = link[static_cast<std::size_t>(root)];
        root = l == root ? root + step : l;
      }
      while (!out(i) && i != root) {
        const int l = link[static_cast<std::size_t>(i)];
        link[static_cast<std::size_t>(i)] = root;
        i = l == i ? i + step : l;
      }
      return root;
    }
  };
  void make(int v, Sorted& s) {
    ef_->for_each_from(v, [&](EfEntry& e) { s.entries.push_back({&e, order_->is_upper(e.dir)}); });
    std::stable_sort(s.entries.begin(), s.entries.end(), [&](const Item& a, const Item& b) {
      return order_->compare_known(a.entry->dir, a.upper, b.entry->dir, b.upper) == Sign::negative;
    });
    s.right.resize(s.entries.size());
    s.left.resize(s.entries.size());
    for (std::size_t i = 0; i < s.entries.size(); ++i) s.right[i] = s.left[i] = static_cast<int>(i);
  }
  const DirectionOrder<K>* order_;
  HashEdgeTable* ef_;
  bool result_on_left_;
  std::unordered_map<int, Sorted> at_;
};

}  // namespace detail

template <Kernel K, class Table>
std::vector<ResultCycle> construct_result_cycles(const Arrangement<K>& arr, Table& ef, Operation op, unsigned threads = 1) {
  const DirectionOrder<K> order(arr.points);
  const PolygonType ta = arr.polygon[0].type;
  const PolygonType tb = arr.polygon[1].type;
  const PolygonType ccw_type = kTable4[op_index(op)][type_index(ta)][type_index(tb)];
  const bool result_on_left = ta == PolygonType::island;
  std::vector<ResultCycle> out;
  if constexpr (std::is_same_v<Table, HashEdgeTable>) {
    if (threads_for(ef.size(), threads) > 1 && detail::forced_cycles(order, ef, ccw_type, threads, out)) return out;
  }

  // The next fragment after arriving at v along `in`: the first one met turning from the
  // reversed arrival direction towards the result region (clockwise when the region lies
  // left). The reverse fragment itself, if selected, comes first: a two-sided part.
  [[maybe_unused]] auto angular = [&] {
    if constexpr (std::is_same_v<Table, HashEdgeTable> && K::is_exact) {
      return detail::AngularChoices<K>(order, ef, result_on_left);
    } else {
      return 0;
    }
  }();
  const auto choose_next = [&](int v, Direction in) -> EfEntry* {
    EfEntry* best = nullptr;
    const Direction back = in.reversed();
    if constexpr (std::is_same_v<Table, HashEdgeTable> && K::is_exact) {
      if (ef.is_long(v)) return angular.choose(v, back);
    }
    ef.for_each_from(v, [&](EfEntry& e) {
      if (best == nullptr) {
        best = &e;
        return;
      }
      if (order.compare(best->dir, back) == Sign::zero) return;
      if (order.compare(e.dir, back) == Sign::zero) {
        best = &e;
        return;
      }
      // e comes first when it lies in the sweep from `back` to `best` in the turning sense.
      const bool e_first = result_on_left ? !order.is_in_ccw_sector(back, best->dir, e.dir)
                                          : order.is_in_ccw_sector(back, best->dir, e.dir);
      if (e_first) best = &e;
    });
    return best;
  };

  // vertex -> its index in the current path, if path_vertices there still holds it: entries
  // left behind by emitted cycles and earlier walks fail that test, so none is ever reset.
  std::vector<int> position(static_cast<std::size_t>(arr.num_vertices()), -1);
  std::vector<int> path_vertices;
  std::vector<Direction> path_dirs;
  const auto on_path = [&](int v) {
    const int at = position[v];
    return at >= 0 && static_cast<std::size_t>(at) < path_vertices.size() && path_vertices[at] == v ? at : -1;
  };
  const auto emit = [&](std::size_t from) {
    ResultCycle cycle;
    if (from == 0) {  // the whole path, moved (one cycle of 10^6 vertices on blob 1e6)
      cycle.vertices = std::move(path_vertices);
      cycle.directions = std::move(path_dirs);
      path_vertices.assign({cycle.vertices[0]});
      path_dirs.clear();
    } else {
      cycle.vertices.assign(path_vertices.begin() + static_cast<std::ptrdiff_t>(from), path_vertices.end());
      cycle.directions.assign(path_dirs.begin() + static_cast<std::ptrdiff_t>(from), path_dirs.end());
      path_vertices.resize(from + 1);
      path_dirs.resize(from);
    }
    if (cycle.vertices.size() >= 3) {
      detail::set_orientation<K>(cycle, detail::turning_number(order, cycle.directions, threads), ccw_type);
    }
    out.push_back(std::move(cycle));
  };

  // An entry's direction, then its inner vertices each with the direction leaving it (a run
  // of fragments through vertices nothing else meets: no choice and no return there).
  const auto append_entry = [&](const EfEntry& e) {
    path_dirs.push_back(e.dir);
    if constexpr (std::is_same_v<Table, HashEdgeTable>) {
      const auto [first, count] = ef.inner_range(e);
      ef.append_inner(first, count, path_vertices, path_dirs);
    }
  };
  // Every walk starts from the first fragment still unused, in EF's insertion order
  // (for_each tests `alive` as it reaches each entry, after the earlier walks).
  ef.for_each([&](EfEntry& start) {
    start.alive = false;
    path_vertices.assign({start.from});
    path_dirs.clear();
    append_entry(start);
    path_vertices.push_back(start.to);
    position[start.from] = 0;
    if (start.to == start.from) throw KernelFailure("degenerate fragment");
    position[start.to] = static_cast<int>(path_vertices.size()) - 1;
    while (path_vertices.size() > 1) {  // ends when a cycle closes at the start vertex
      const int v = path_vertices.back();
      EfEntry* next = choose_next(v, path_dirs.back());
      if (next == nullptr) {
        throw KernelFailure(std::string("kernel ") + std::string(K::name) + ": a result polygon does not close");
      }
      next->alive = false;
      append_entry(*next);
      if (const int at = on_path(next->to); at >= 0) {
        emit(static_cast<std::size_t>(at));
      } else {
        position[next->to] = static_cast<int>(path_vertices.size());
        path_vertices.push_back(next->to);
      }
    }
  });
  return out;
}

// Step 6 as the driver calls it: the cycles traced through EF, then the isolated points of
// step 5 as one-sided result polygons.
template <Kernel K, class Table>
std::vector<ResultCycle> construct_result_polygons(const Arrangement<K>& arr, Table& ef, Operation op,
                                                   const std::vector<int>& isolated_points, unsigned threads = 1) {
  std::vector<ResultCycle> out = construct_result_cycles(arr, ef, op, threads);
  for (const int v : isolated_points) out.push_back({{v}, {}, PolygonType::island, true});
  return out;
}

}  // namespace mk
