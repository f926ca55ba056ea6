// Step 4: classify the edge fragments. For every fragment, the winding depth of A and of B
// just left and right of it, from which inside / outside / boundary-same /
// boundary-opposite follow [MK89 §3.1 step 4].
// [MK89 §4.3] (walk each vertex ring from one located vertex, updating at boundary points:
// Table 5's angle rules, generalised to vertices of any degree)
// Preconditions: step 3 done. Only orientations of input points are evaluated: crossing
// points are never located by coordinates.
#pragma once

#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/arrangement.hpp"
#include "core/error.hpp"
#include "core/incidence.hpp"
#include "core/locator.hpp"
#include "core/parallel.hpp"
#include "predicates/ray.hpp"

namespace mk {

template <Kernel K>
WindingLocator<K> make_locator(const Arrangement<K>& arr, const PreparedPolygon& x, std::size_t queries) {
  return WindingLocator<K>(arr, x.edges, queries);
}

namespace detail {

// Walks one cycle of polygon p and records the winding depth of polygon x on both sides of
// each fragment. Sweeping counterclockwise over a fragment end of x at a vertex raises the
// depth when the fragment leaves the vertex (x's region is on its left) and lowers it when
// it arrives.
template <Kernel K>
void walk_cycle(const Arrangement<K>& arr, PreparedPolygon& p, int c, int xi, const Incidence& inc, int anchor) {
  const PreparedPolygon& x = arr.polygon[xi];
  const FragmentEndTable& x_ends = inc.ends[xi];
  const DirectionOrder<K> order(arr.points);
  const int first = p.cycle_first_fragment[c];
  const int last = p.cycle_first_fragment[c + 1];
  int left = anchor;
  // At a vertex where only the ring's own two fragments meet (count 2 in its own table),
  // those two fragment ends are known without reading them: the fragment arriving and the one leaving.
  const bool own = &x == &p;
  for (int i = first; i < last; ++i) {
    Fragment& f = p.fragments[i];
    const Fragment& next = p.fragments[i + 1 < last ? i + 1 : first];
    int same = 0;
    int opposite = 0;
    if (own && x_ends.count(f.from) == 2) {
      same = 1;  // f itself; the other end is the previous fragment arriving
      opposite = p.fragments[i > first ? i - 1 : last - 1].from == f.to ? 1 : 0;
    } else {
      std::tie(same, opposite) = fragments_along(x, x_ends, f.from, f.to);
    }
    f.far_left[xi] = x.far_sign * left;
    f.far_right[xi] = x.far_sign * (left - (same - opposite));
    if (own ? x_ends.count(f.to) == 2 : !x_ends.reaches(f.to)) continue;  // no fragment end between f and next
    const Edge& ein = p.edges[f.edge];
    const Edge& eout = p.edges[next.edge];
    const Direction back{ein.dst, ein.src};
    const Direction ahead{eout.src, eout.dst};
    // The left side of `next` is reached from the left side of f by sweeping clockwise
    // from `back` to `ahead`, i.e. through the counterclockwise sector ahead -> back.
    if constexpr (K::is_exact) {
      if (const int m = x_ends.many(f.to); m >= 0 && x_ends.by_angle_ready()) {  // two binary searches
        left -= x_ends.signs_in_sweep(order, m, ahead, back);
        continue;
      }
    }
    int delta = 0;
    std::optional<typename DirectionOrder<K>::Sector> sector;  // made at the first end tested
    for (const FragmentEnd& end : x_ends.at(f.to)) {
      // A fragment along `back` or `ahead` themselves lies on the sector's boundary, never
      // strictly inside: at the vertices of p's own ring no predicate is evaluated.
      const Direction dir = end.dir();
      if (dir == back || dir == ahead) continue;
      if (!sector) sector.emplace(order, ahead, back);
      if (sector->contains(dir)) delta += end.sign();
    }
    left -= delta;
  }
  if (left != anchor) {
    throw KernelFailure(std::string("kernel ") + std::string(K::name) +
                        ": the classification of a vertex ring does not close (inconsistent predicates)");
  }
}

}  // namespace detail

template <Kernel K>
Incidence classify_fragments(Arrangement<K>& arr, unsigned threads = 1) {
  const int nv = arr.num_vertices();
  const std::size_t work = arr.polygon[0].fragments.size() + arr.polygon[1].fragments.size();
  const unsigned t = threads_for(work, threads);
  Incidence inc;
  run_tasks(t, 2, [&](std::size_t p) {
    inc.ends[p] = FragmentEndTable(arr.polygon[p], nv);
    if constexpr (K::is_exact) inc.ends[p].order_by_angle(DirectionOrder<K>(arr.points));
  });
  // [MK89 §4.3 step 1] One located point per ring: just left of its first fragment. Each
  // locator answers the queries of every cycle of A and of B in one batch.
  std::vector<LocatorQuery> queries;
  for (const auto& p : arr.polygon) {
    for (int c = 0; c + 1 < static_cast<int>(p.cycle_first_fragment.size()); ++c) {
      const Edge& e0 = p.edges[p.fragments[p.cycle_first_fragment[c]].edge];
      queries.push_back({e0.src, e0.dst, Side::left});
    }
  }
  std::array<std::vector<int>, 2> anchors;
  run_tasks(t, 2, [&](std::size_t x) { anchors[x] = make_locator(arr, arr.polygon[x], queries.size()).windings(queries); });
  // The two polygons' rings are walked on separate threads: a walk writes the depths of its
  // own polygon's fragments only.
  const int first_of_b = static_cast<int>(arr.polygon[0].cycle_first_fragment.size()) - 1;
  run_tasks(t, 2, [&](std::size_t pi) {
    PreparedPolygon& p = arr.polygon[pi];
    const int q0 = pi == 0 ? 0 : first_of_b;
    for (int c = 0; c + 1 < static_cast<int>(p.cycle_first_fragment.size()); ++c) {
      detail::walk_cycle(arr, p, c, 0, inc, anchors[0][q0 + c]);
      detail::walk_cycle(arr, p, c, 1, inc, anchors[1][q0 + c]);
    }
  });
  return inc;
}

// FAR depth of polygon x at input point v, which lies on none of x's edges.
template <Kernel K>
int far_depth_at(const Arrangement<K>& arr, int xi, int v) {
  const PreparedPolygon& x = arr.polygon[xi];
  if (arr.num_points() < 2) return 0;
  const int t = v == 0 ? 1 : 0;  // any other input point: v is on no edge of x
  return x.far_sign * make_locator(arr, x, 1).winding(v, t, Side::left);
}

}  // namespace mk
