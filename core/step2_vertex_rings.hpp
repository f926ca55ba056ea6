// Step 2: insert the original vertices of A and B into their vertex rings AV and BV.
// [MK89 §3.1 step 2] [MK89 §3.3] (vertex rings as linked lists)
// Preconditions: orientations normalised (step 1). Vertex classification, which the paper
// does here by point-in-polygon tests, is done in step 4 by walking the rings [MK89 §4.3].
#pragma once

#include <array>
#include <cstddef>

#include "core/arrangement.hpp"
#include "core/parallel.hpp"

namespace mk {

// Lays out every cycle's edges in ring order; fragments follow in step 3. The two polygons
// on two threads when there are enough edges.
template <Kernel K>
void build_vertex_rings(Arrangement<K>& arr, unsigned threads = 1) {
  std::array<std::size_t, 2> total{0, 0};  // edges per polygon: one per cycle vertex
  for (std::size_t p = 0; p < 2; ++p) {
    for (const auto& cycle : arr.polygon[p].cycles) total[p] += cycle.size();
  }
  run_tasks(threads_for(total[0] + total[1], threads), 2, [&](std::size_t p) {
    PreparedPolygon& poly = arr.polygon[p];
    poly.edges.clear();
    poly.cycle_first_edge.assign(1, 0);
    poly.edges.reserve(total[p]);
    poly.cycle_first_edge.reserve(poly.cycles.size() + 1);
    for (int c = 0; c < static_cast<int>(poly.cycles.size()); ++c) {
      const auto& cycle = poly.cycles[c];
      // Made in place, without a division per vertex for the wrap-around (cycles have 2+ vertices).
      // In place, fields set (no parenthesised aggregate init in clang 14, the fuzzers').
      const auto add = [&](int src, int dst) {
        Edge& e = poly.edges.emplace_back();
        e.src = src;
        e.dst = dst;
      };
      for (std::size_t i = 0; i + 1 < cycle.size(); ++i) add(cycle[i], cycle[i + 1]);
      add(cycle.back(), cycle.front());
      poly.cycle_first_edge.push_back(static_cast<int>(poly.edges.size()));
    }
  });
}

}  // namespace mk
