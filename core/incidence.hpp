// Incidence of edge fragments at vertices (the rays leaving a vertex along fragments) and
// counts of fragments that coincide as sets; used by steps 4 and 5.
// [MK89 §4.3] (classification at boundary points) [MK89 §3.3] (EF: matching fragments)
// Preconditions: step 3 done.
#pragma once

#include <vector>

#include "core/arrangement.hpp"
#include "predicates/directions.hpp"

namespace mk {

// A fragment seen from one of its endpoints: the direction away from that endpoint (given
// by the original edge's input points), +1 when the fragment leaves the vertex, -1 when it
// arrives, and the fragment's index.
struct Ray {
  Direction dir;
  int sign = 0;
  int fragment = -1;
};

class RayTable {
 public:
  RayTable() = default;
  RayTable(const PreparedPolygon& poly, int num_vertices) {
    begin_.assign(static_cast<std::size_t>(num_vertices) + 1, 0);
    for (const auto& f : poly.fragments) {
      ++begin_[f.from + 1];
      ++begin_[f.to + 1];
    }
    for (std::size_t i = 1; i < begin_.size(); ++i) begin_[i] += begin_[i - 1];
    rays_.resize(static_cast<std::size_t>(begin_.back()));
    std::vector<int> fill(begin_.begin(), begin_.end() - 1);
    for (int i = 0; i < static_cast<int>(poly.fragments.size()); ++i) {
      const auto& f = poly.fragments[i];
      const auto& e = poly.edges[f.edge];
      rays_[fill[f.from]++] = {{e.src, e.dst}, +1, i};
      rays_[fill[f.to]++] = {{e.dst, e.src}, -1, i};
    }
  }
  struct Span {
    const Ray* b;
    const Ray* e;
    const Ray* begin() const { return b; }
    const Ray* end() const { return e; }
    bool empty() const { return b == e; }
  };
  Span at(int v) const { return {rays_.data() + begin_[v], rays_.data() + begin_[v + 1]}; }

 private:
  std::vector<int> begin_;
  std::vector<Ray> rays_;
};

// Fragments of polygon x lying on u -> w: (same direction, opposite direction), found among
// x's rays at u, which are few.
inline std::pair<int, int> fragments_along(const PreparedPolygon& x, const RayTable& x_rays, int u, int w) {
  int same = 0;
  int opposite = 0;
  for (const Ray& r : x_rays.at(u)) {
    const Fragment& f = x.fragments[r.fragment];
    if (r.sign > 0 && f.to == w) ++same;
    if (r.sign < 0 && f.from == w) ++opposite;
  }
  return {same, opposite};
}

}  // namespace mk
