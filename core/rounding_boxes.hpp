// The box certificate (core/box_certificate.hpp) applied to a result's cycles rounded to
// their nearest doubles: each vertex's box made from the kernel's box about its exact point,
// and the polygons' edges between them.
// [HP02] [GM98] [MK89 §3.3]
// Preconditions: the exact result is valid (to_output.hpp); K gives each vertex a box that
// certainly holds it (VertexBoxes). False means "not certified", never "invalid".
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "core/boolean_op.hpp"
#include "core/box_certificate.hpp"
#include "core/parallel.hpp"
#include "core/separation_rules.hpp"

namespace mk {

// Per cycle, per vertex: the half-sizes (x, y) of a box about the vertex's rounded point
// that holds its exact position, made while rounding (the vertex is at hand then). One
// array for all cycles, their vertices one after another (`first[c]` is cycle c's first):
// one allocation instead of one per cycle (star 1e4 has 60,737 cycles).
struct RoundingHalves {
  std::vector<std::size_t> first;  // size cycles + 1 once made
  std::vector<std::array<double, 2>> sizes;
  bool empty() const { return first.empty(); }
  const std::array<double, 2>& at(std::size_t cycle, std::size_t k) const { return sizes[first[cycle] + k]; }
};

namespace detail {

// The half-sizes for vertex `id` of r (the value v) rounded to `at`: none for an input point
// of doubles (it rounds to itself), else the kernel's box about `at` (`at` lies in the box
// when rounded to nearest).
template <VertexBoxes K>
std::array<double, 2> rounding_half_sizes(const BooleanResult<K>& r, int id, const typename K::Vertex& v, const Point& at) {
  if (std::is_same_v<typename K::Point, Point> && r.arrangement.is_input_point(id)) return {0.0, 0.0};
  const auto half = [](double p, double lo, double hi) { return rounded_up(std::max({p - lo, hi - p, 0.0})); };
  const std::array<double, 4> box = K::vertex_box(v);  // x0, y0, x1, y1
  return {half(at.x, box[0], box[2]), half(at.y, box[1], box[3])};
}

// The certificate's vertices (each once, with its box) and the polygons' edges between them;
// the half-sizes from `halves` when given (see rounded_cycles), else from the kernel.
template <VertexBoxes K>
void rounded_vertex_boxes(const BooleanResult<K>& r, const std::vector<std::vector<Point>>& rounded,
                          const std::vector<std::vector<int>>& polygon_cycles, std::vector<RoundedVertexBox>& boxes,
                          std::vector<std::array<int, 2>>& edges, const RoundingHalves* halves = nullptr) {
  std::vector<int> slot(static_cast<std::size_t>(r.arrangement.num_vertices()), -1);
  std::size_t total = 0;
  for (const auto& cycles : polygon_cycles) {
    for (const int c : cycles) total += r.cycles[static_cast<std::size_t>(c)].vertices.size();
  }
  boxes.reserve(total);
  edges.reserve(total);
  for (const auto& cycles : polygon_cycles) {
    for (const int c : cycles) {
      const auto& ids = r.cycles[static_cast<std::size_t>(c)].vertices;
      const std::size_t n = ids.size();
      for (std::size_t k = 0; k < n; ++k) {
        int& s = slot[static_cast<std::size_t>(ids[k])];
        if (s >= 0) continue;
        s = static_cast<int>(boxes.size());
        const Point at = rounded[static_cast<std::size_t>(c)][k];
        const std::array<double, 2> h = halves && !halves->empty() ? halves->at(static_cast<std::size_t>(c), k)
                                                                    : rounding_half_sizes(r, ids[k], r.vertex(ids[k]), at);
        boxes.push_back({at, h[0], h[1]});
      }
      for (std::size_t k = 0; k < n; ++k) {
        edges.push_back({slot[static_cast<std::size_t>(ids[k])], slot[static_cast<std::size_t>(ids[(k + 1) % n])]});
      }
    }
  }
}

}  // namespace detail

// The certificate for a result's polygons (each a list of cycle indices), given the
// cycles' rounded vertices: true when it proves the rounded polygons valid.
template <VertexBoxes K>
bool rounding_boxes_keep_topology(const BooleanResult<K>& r, const std::vector<std::vector<Point>>& rounded,
                                  const std::vector<std::vector<int>>& polygon_cycles, unsigned threads = 1,
                                  const RoundingHalves* halves = nullptr) {
  std::vector<detail::RoundedVertexBox> boxes;
  std::vector<std::array<int, 2>> edges;
  detail::rounded_vertex_boxes(r, rounded, polygon_cycles, boxes, edges, halves);
  return detail::boxes_keep_topology(boxes, edges, false, threads);
}

// Rule I, and the rest of the certificate: true when step 3 proved rules N and C
// (arr.separation) and every input point is more than T from every input edge it does not
// end. False means "not certified", never "invalid". The vertices' boxes need not be made:
// a crossing's box has double bounds holding its exact point, so the nearest double lies in
// it too, and the box about that double (half-sizes the larger distance to the bounds,
// rounded up, as rounding_half_sizes makes them) is within its extent, so within R, by
// the monotony of rounding (separation_rules_test checks it exactly).
template <Kernel K>
bool rounding_rules_keep_topology(const BooleanResult<K>& r, unsigned threads = 1) {
  if constexpr (!std::is_same_v<typename K::Point, Point>) {
    return false;  // never proved (CrossingSegments)
  } else {
    const Arrangement<K>& arr = r.arrangement;
    const double big_t = arr.separation.threshold;
    if (!(big_t > 0)) return false;
    // Every point's box of half-size T/2 clear of the hull of every edge it does not end (the
    // hull within T/2 of the segment): then the point is more than T from the edge.
    const double half = detail::rounded_up(big_t / 2 * (1 + 0x1p-52));
    std::vector<std::array<int, 2>> edges;
    for (const PreparedPolygon& poly : arr.polygon) {
      for (const auto& cycle : poly.cycles) {
        for (std::size_t k = 0; k < cycle.size(); ++k) edges.push_back({cycle[k], cycle[(k + 1) % cycle.size()]});
      }
    }
    return detail::points_clear_of_edges(arr.points, half, edges, threads);
  }
}

}  // namespace mk
