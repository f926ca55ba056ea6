// Turns a kernel's result into the kernel-independent Output: irreducible polygons with
// types, OGC polygons-with-holes through the inclusion forest, non-regular parts, and for
// exact kernels whether the rounded coordinates are still a valid output.
// [MK89 §2.2] (inclusion forest) [MK89 §3.3] (detecting non-orientable rounded output)
// Preconditions: `result` comes from boolean_op with kernel K; V is an exact kernel over
// doubles (its Point constructible from mk::Point) used to check the rounded output.
#pragma once

#include <string>
#include <vector>

#include "core/assemble.hpp"
#include "core/boolean_op.hpp"
#include "core/output.hpp"
#include "core/pairs.hpp"
#include "predicates/segments.hpp"

namespace mk {

// Whether rings of doubles form a valid output: no ring collapses (repeated consecutive
// points; area rings need three distinct points), no two edges cross or overlap, and no
// vertex lies inside another edge. Decided exactly by kernel V.
template <Kernel V>
bool is_valid_rounded_output(const std::vector<std::vector<Point>>& rings) {
  std::vector<Point> raw;
  std::vector<std::pair<std::size_t, std::size_t>> edges;  // indices into raw
  for (const auto& r : rings) {
    const std::size_t base = raw.size();
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (r.size() > 1 && r[i] == r[(i + 1) % r.size()]) return false;
      raw.push_back(r[i]);
      if (r.size() > 1 && !(r.size() == 2 && i == 1)) edges.push_back({base + i, base + (i + 1) % r.size()});
    }
  }
  // Identities of the rounded points, in lexicographic order as pairs.h requires.
  std::vector<std::size_t> order(raw.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return raw[a].x != raw[b].x ? raw[a].x < raw[b].x : raw[a].y < raw[b].y;
  });
  std::vector<typename V::Point> pts;
  std::vector<int> id(raw.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k == 0 || !(raw[order[k]] == raw[order[k - 1]])) pts.push_back(V::point(raw[order[k]]));
    id[order[k]] = static_cast<int>(pts.size()) - 1;
  }
  std::vector<int> x_rank(pts.size(), 0);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    x_rank[i] = x_rank[i - 1] + (V::compare_x(pts[i - 1], pts[i]) != Sign::zero);
  }
  std::vector<SweepItem> items;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const auto [s, e] = edges[k];
    items.push_back(sweep_item(id[s], id[e], 0, k > 0 && edges[k - 1].second == s));
  }
  bool valid = true;
  for_each_candidate_pair<V>(pts, x_rank, items, false, PairSearch::sweep, [&](int i, int j) {
    if (!valid) return;
    const SweepItem& a = items[i];
    const SweepItem& b = items[j];
    if (a.lo == b.lo && a.hi == b.hi) {
      valid = false;  // the same segment twice
      return;
    }
    const auto rel = relate_segments<V>(pts[a.lo], pts[a.hi], pts[b.lo], pts[b.hi]);
    if (rel.proper_crossing || rel.touches()) valid = false;
  });
  return valid;
}

// `exact_coordinates`: also write each vertex's exact coordinates as strings (exact kernels),
// which costs more than rounding them.
template <Kernel K, Kernel V>
Output to_output(const BooleanResult<K>& r, bool exact_coordinates = true) {
  Output out;
  out.unbounded = r.unbounded;
  std::vector<std::vector<Point>> rounded;
  for (const auto& c : r.cycles) {
    OutputIrreducible o;
    o.type = c.type;
    for (const int id : c.vertices) {
      o.vertices.push_back(K::approx(r.vertex(id)));
      if (K::is_exact && exact_coordinates) {
        const auto e = K::exact_coordinates(r.vertex(id));
        o.exact.push_back(e[0]);
        o.exact.push_back(e[1]);
      }
    }
    if (c.vertices.size() == 1) out.isolated_points.push_back(o.vertices[0]);
    if (c.vertices.size() == 2) out.dangling_edges.push_back({o.vertices[0], o.vertices[1]});
    rounded.push_back(o.vertices);
    out.irreducible.push_back(std::move(o));
  }
  if constexpr (K::is_exact) out.rounded_valid = is_valid_rounded_output<V>(rounded);
  if (!r.unbounded) {
    const std::vector<int> parent = inclusion_parents(r.arrangement, r.cycles);
    std::vector<int> shell_of(r.cycles.size(), -1);
    for (std::size_t i = 0; i < r.cycles.size(); ++i) {
      if (r.cycles[i].vertices.size() < 3 || r.cycles[i].type != PolygonType::island) continue;
      shell_of[i] = static_cast<int>(out.polygons.size());
      out.polygons.push_back({out.irreducible[i].vertices, {}});
    }
    for (std::size_t i = 0; i < r.cycles.size(); ++i) {
      if (r.cycles[i].vertices.size() < 3 || r.cycles[i].type != PolygonType::hole) continue;
      if (parent[i] >= 0 && shell_of[parent[i]] >= 0) {
        out.polygons[shell_of[parent[i]]].holes.push_back(out.irreducible[i].vertices);
      }
    }
  }
  return out;
}

}  // namespace mk
