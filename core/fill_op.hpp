// Boolean operations of regions given by fill rules, and N-ary unions and intersections: the
// paper's classification generalised from inside/outside to winding numbers. Every link of
// the winding arrangement gets the winding number of every input on both its sides, by
// walking around each vertex in angular order from one link located by a ray per connected
// part; a link bounds the result where the result's predicate differs across it, and the
// result cycles are traced by step 6.
// [MK89 §3.1 steps 4-6] [MK89 §4.3] (locate one point, then walk, updating at boundaries)
// [MK89 Table 5] (angles at a vertex) paper-notes.md, deviation "winding numbers"
// Preconditions: `wa` from build_winding_arrangement; in_result(const int* w) reads one
// winding number per group and says whether that face is in the result.
#pragma once

#include <algorithm>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "core/boolean_op.hpp"
#include "core/edge_fragment_table.hpp"
#include "core/error.hpp"
#include "core/locator.hpp"
#include "core/step6_construct.hpp"
#include "core/winding_arrangement.hpp"
#include "core/sorting.hpp"
#include "predicates/directions.hpp"
#include "predicates/ray.hpp"

namespace mk {

// The ends of the links grouped by vertex: ends[begin[v], begin[v + 1]) are v's, each with
// its code, 2 l at link l's lo and 2 l + 1 at its hi, and the vertex at the link's other
// end (so that walking around v reads no link).
struct LinkEnd {
  int code;
  int other;
};
struct LinkEnds {
  std::vector<int> begin;
  std::vector<LinkEnd> ends;
};

inline LinkEnds link_ends_by_vertex(const std::vector<WindingLink>& links, int num_vertices) {
  LinkEnds g;
  g.begin.assign(static_cast<std::size_t>(num_vertices) + 1, 0);
  for (const WindingLink& l : links) {
    ++g.begin[l.lo + 1];
    ++g.begin[l.hi + 1];
  }
  for (std::size_t v = 1; v < g.begin.size(); ++v) g.begin[v] += g.begin[v - 1];
  g.ends.resize(static_cast<std::size_t>(g.begin.back()));
  std::vector<int> fill(g.begin.begin(), g.begin.end() - 1);
  for (std::size_t l = 0; l < links.size(); ++l) {
    g.ends[fill[links[l].lo]++] = LinkEnd{2 * static_cast<int>(l), links[l].hi};
    g.ends[fill[links[l].hi]++] = LinkEnd{2 * static_cast<int>(l) + 1, links[l].lo};
  }
  return g;
}

// The winding numbers of every group just left of every link (left of lo -> hi), flattened
// link after link. Exact with exact kernels; KernelFailure when inexact predicates make the
// counts around a vertex disagree.
template <Kernel K>
std::vector<int> link_windings(const WindingArrangement<K>& wa) {
  const Arrangement<K>& arr = wa.arr;
  const int num_links = static_cast<int>(wa.links.size());
  // Counted apart, the groups cost a winding number each per link: refused past 2^27 numbers
  // (512 MB) rather than exhausting memory.
  if (static_cast<double>(num_links) * wa.groups > static_cast<double>(1 << 27)) {
    throw InvalidInput(std::to_string(wa.groups) + " inputs counted apart on " + std::to_string(num_links) +
                       " links would need more than 2^27 winding numbers; give fewer inputs (intersection-all keeps one "
                       "per part)");
  }
  // Link ends grouped by vertex, each group then put in angular order.
  LinkEnds grouped = link_ends_by_vertex(wa.links, arr.num_vertices());
  const std::vector<int>& begin = grouped.begin;
  std::vector<LinkEnd>& ends = grouped.ends;
  const DirectionOrder<K> angles(arr.points);
  const auto dir_of = [&](int code) {
    const Direction d = wa.links[code >> 1].dir;
    return (code & 1) != 0 ? d.reversed() : d;
  };
  for (std::size_t v = 0; v + 1 < begin.size(); ++v) {
    if (begin[v + 1] - begin[v] < 3) continue;  // two ends: either order is the angular one
    sort_by_predicates<K>(ends.begin() + begin[v], ends.begin() + begin[v + 1],
              [&](const LinkEnd& x, const LinkEnd& y) { return angles.compare(dir_of(x.code), dir_of(y.code)) == Sign::negative; });
  }

  std::vector<int> left(static_cast<std::size_t>(num_links) * wa.groups, 0);
  // The walk, its group loops unrolled for one group (union-all, make-valid): kG groups, or
  // wa.groups when kG is 0.
  const auto walk = [&](auto fixed_groups) {
    constexpr int kG = decltype(fixed_groups)::value;
    const int G = kG > 0 ? kG : wa.groups;
    std::vector<char> known(static_cast<std::size_t>(num_links), 0);
    std::vector<char> done(static_cast<std::size_t>(arr.num_vertices()), 0);
    const auto delta = [&](int l, int g) { return wa.delta[static_cast<std::size_t>(l) * G + g]; };
    const auto fail = [&]() {
      throw KernelFailure(std::string("kernel ") + std::string(K::name) +
                          ": the winding numbers around a vertex do not close (inconsistent predicates)");
    };
    std::vector<int> stack;
    std::vector<int> sector(static_cast<std::size_t>(G));
    // Around v counterclockwise: crossing an end counterclockwise goes from the right of its
    // ray (away from v) to its left, adding the ray's net count; the sector after an end at
    // lo is its link's left side, after an end at hi its right side.
    const auto walk_around = [&](int v) {
      const int b = begin[v];
      const int n = begin[v + 1] - b;
      int i0 = 0;
      while (i0 < n && !known[ends[b + i0].code >> 1]) ++i0;
      const auto after = [&](int code, int g) {
        const int l = code >> 1;
        return left[static_cast<std::size_t>(l) * G + g] - ((code & 1) != 0 ? delta(l, g) : 0);
      };
      for (int g = 0; g < G; ++g) sector[g] = after(ends[b + i0].code, g);
      int i = i0;
      for (int k = 1; k <= n; ++k) {
        if (++i == n) i = 0;
        const int code = ends[b + i].code;
        const int l = code >> 1;
        for (int g = 0; g < G; ++g) sector[g] += (code & 1) != 0 ? -delta(l, g) : delta(l, g);
        if (known[l]) {
          for (int g = 0; g < G; ++g) {
            if (after(code, g) != sector[g]) fail();
          }
          continue;
        }
        for (int g = 0; g < G; ++g) left[static_cast<std::size_t>(l) * G + g] = sector[g] + ((code & 1) != 0 ? delta(l, g) : 0);
        known[l] = 1;
        const int other = ends[b + i].other;
        if (!done[other]) stack.push_back(other);
      }
    };

    // One located link per connected part: the first fragment of an edge, whose left side
    // is the point just left of the edge near its source (a ray query over each group's
    // edges). The first few queries scan the edges; from then on (many separate parts) they
    // read the edges near them in x (the edges cross: no sweep).
    std::vector<std::unique_ptr<WindingLocator<K>>> locators(static_cast<std::size_t>(G));
    std::vector<char> bucketed(static_cast<std::size_t>(G), 0);
    constexpr int kDirectSeeds = 4;
    int seeds = 0;
    const auto locate = [&](int e, int g) {
      if (!locators[g]) {
        const std::span<const Edge> edges(wa.edges.data() + wa.group_first_edge[g],
                                          static_cast<std::size_t>(wa.group_first_edge[g + 1] - wa.group_first_edge[g]));
        locators[g] = std::make_unique<WindingLocator<K>>(arr, edges, 1);
      }
      if (seeds > kDirectSeeds && !bucketed[g]) {
        locators[g]->index_for_scans();
        bucketed[g] = 1;
      }
      return locators[g]->winding(wa.edges[e].src, wa.edges[e].dst, Side::left);
    };
    for (int e = 0; e < static_cast<int>(wa.edges.size()); ++e) {
      const int l = wa.edge_first_link[e];
      if (known[l]) continue;
      ++seeds;
      for (int g = 0; g < G; ++g) {
        const bool empty = wa.group_first_edge[g] == wa.group_first_edge[g + 1];
        const int w = empty ? 0 : locate(e, g);
        left[static_cast<std::size_t>(l) * G + g] = wa.edge_first_forward[e] ? w : w + delta(l, g);
      }
      known[l] = 1;
      stack.assign({wa.links[l].lo, wa.links[l].hi});
      while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        if (done[v]) continue;
        done[v] = 1;
        walk_around(v);
      }
    }
  };
  if (wa.groups == 1) {
    walk(std::integral_constant<int, 1>());
  } else {
    walk(std::integral_constant<int, 0>());
  }
  return left;
}

// The result of a predicate over the groups' winding numbers: its boundary links, oriented
// with the result on their left, traced into cycles by step 6. Non-regular (`in_closed`
// given): also the links and vertices that the closed-set operation keeps where no result
// face is beside them, as two-sided parts (both directions of a link) and one-sided parts
// (a vertex). in_closed(faces) says whether a point whose neighbourhood meets exactly the
// faces listed (each a pointer to one winding number per group; two for a link's relative
// interior, every sector around a vertex) is in the closed result: an input's closure holds
// the point when one of those faces is in the input's region, its interior when all are.
// [MK89 §2.3] (closed-set operations) [MK89 §3.2] (two-sided and one-sided parts)
template <Kernel K, class InResult, class InClosed>
BooleanResult<K> fill_op(WindingArrangement<K>&& wa, InResult&& in_result, const InClosed* in_closed) {
  const int G = wa.groups;
  const std::vector<int> left = link_windings(wa);
  BooleanResult<K> res;
  Arrangement<K>& arr = res.arrangement;
  arr = std::move(wa.arr);
  HashEdgeTable ef((in_closed != nullptr ? 2 : 1) * wa.links.size(), arr.num_vertices());
  // The winding numbers right of link l: left minus the link's net count.
  const auto right_of = [&](std::size_t l, int* out) {
    for (int g = 0; g < G; ++g) out[g] = left[l * G + g] - wa.delta[l * G + g];
  };
  std::vector<int> right(static_cast<std::size_t>(G));
  std::vector<const int*> faces;
  for (std::size_t l = 0; l < wa.links.size(); ++l) {
    const int* wl = left.data() + l * G;
    right_of(l, right.data());
    const bool in_left = in_result(wl);
    const WindingLink& k = wa.links[l];
    if (in_left == in_result(right.data())) {
      if (in_closed == nullptr || in_left) continue;
      faces.assign({wl, right.data()});
      if (!(*in_closed)(faces)) continue;
      ef.insert(EfEntry{k.lo, k.hi, k.dir, true}, false);  // a two-sided part: both directions
      ef.insert(EfEntry{k.hi, k.lo, k.dir.reversed(), true}, false);
      continue;
    }
    ef.insert(in_left ? EfEntry{k.lo, k.hi, k.dir, true} : EfEntry{k.hi, k.lo, k.dir.reversed(), true}, in_closed == nullptr);
  }
  // Both (empty) polygons are islands: counterclockwise cycles are islands (Table 4, union).
  std::vector<int> isolated;
  if (in_closed != nullptr) {
    // A vertex that no kept link touches and no result face surrounds (then it would be
    // inside the result) is a one-sided part when the closed-set result holds it.
    std::vector<char> touched(static_cast<std::size_t>(arr.num_vertices()), 0);
    ef.for_each([&](const EfEntry& e) { touched[e.from] = touched[e.to] = 1; });
    const LinkEnds around = link_ends_by_vertex(wa.links, arr.num_vertices());
    std::vector<int> sides;  // the windings right of each link at the vertex
    for (int v = 0; v < arr.num_vertices(); ++v) {
      const int b = around.begin[v], e = around.begin[v + 1];
      if (touched[v] || b == e) continue;
      sides.resize(static_cast<std::size_t>(e - b) * G);
      faces.clear();
      for (int i = b; i < e; ++i) {
        const std::size_t l = static_cast<std::size_t>(around.ends[i].code >> 1);
        int* wr = sides.data() + static_cast<std::size_t>(i - b) * G;
        right_of(l, wr);
        faces.push_back(left.data() + l * G);
        faces.push_back(wr);
      }
      const bool any_in_result = std::any_of(faces.begin(), faces.end(), [&](const int* w) { return in_result(w); });
      if (!any_in_result && (*in_closed)(faces)) isolated.push_back(v);
    }
  }
  res.cycles = construct_result_polygons(arr, ef, Operation::union_, isolated);
  const std::vector<int> zero(static_cast<std::size_t>(G), 0);
  res.unbounded = in_result(zero.data());
  res.stats.vertices_in = arr.points.size();
  res.stats.crossings = static_cast<std::size_t>(wa.distinct_crossings);
  for (const auto& c : res.cycles) res.stats.vertices_out += c.vertices.size();
  return res;
}

// The regular result of a predicate over the groups' winding numbers.
template <Kernel K, class InResult>
BooleanResult<K> fill_op(WindingArrangement<K>&& wa, InResult&& in_result) {
  using Closed = bool (*)(const std::vector<const int*>&);
  return fill_op<K>(std::move(wa), in_result, static_cast<const Closed*>(nullptr));
}

}  // namespace mk
