// The kernel concept: everything the algorithm may ask of geometry. The core sees no numbers.
// [MK89 §3.3] (numerical accuracy: the decisions must be exact) [Sh97] [At20]
// Preconditions: a kernel's Point values come from finite doubles (or exact rationals).
#pragma once

#include <array>
#include <concepts>
#include <string>
#include <string_view>

#include "kernel/point.hpp"
#include "kernel/sign.hpp"

namespace mk {

// A kernel is a compile-time policy. `Point` is an input vertex; `Vertex` is any vertex of
// the arrangement: an input point or the crossing of two input segments (which a kernel
// may construct, round or keep implicit). Predicates on input points drive every decision
// of the algorithm; Vertex predicates only order crossings along an edge and assemble the
// output.
template <class K>
concept Kernel = requires(const typename K::Point& p, const typename K::Vertex& v, const mk::Point& d) {
  { K::name } -> std::convertible_to<std::string_view>;
  { K::is_exact } -> std::convertible_to<bool>;
  { K::point(d) } -> std::same_as<typename K::Point>;
  { K::compare_x(p, p) } -> std::same_as<Sign>;
  { K::compare_y(p, p) } -> std::same_as<Sign>;
  // Sign of (b - a) x (c - a): positive when c is left of the directed line a -> b.
  { K::orient2d(p, p, p) } -> std::same_as<Sign>;
  // Sign of (q1 - p1) x (q2 - p2): the turn from one edge direction to another.
  { K::orient_vectors(p, p, p, p) } -> std::same_as<Sign>;
  { K::vertex(p) } -> std::same_as<typename K::Vertex>;
  // The crossing point of segments a0a1 and b0b1, which cross properly.
  { K::crossing(p, p, p, p) } -> std::same_as<typename K::Vertex>;
  // Lexicographic (x, then y) comparison of vertices.
  { K::compare_vertices(v, v) } -> std::same_as<Sign>;
  // Order of two vertices lying on segment s -> d: negative when the first comes first.
  { K::compare_along(p, p, v, v) } -> std::same_as<Sign>;
  { K::orient_vertices(v, v, v) } -> std::same_as<Sign>;
  // Output only: nearest doubles, and exact decimal rationals "p/q" for exact kernels.
  { K::approx(v) } -> std::same_as<mk::Point>;
  { K::exact_coordinates(v) } -> std::same_as<std::array<std::string, 2>>;
};

// Optional: a box {x0, y0, x1, y1} that certainly holds a vertex (an input point's box is
// the point). Output checks use it to prove rounding harmless without exact arithmetic.
template <class K>
concept VertexBoxes = Kernel<K> && requires(const typename K::Vertex& v) {
  { K::vertex_box(v) } -> std::same_as<std::array<double, 4>>;
};

}  // namespace mk
