// RoundedCrossingKernel: the shape shared by every kernel that decides on input points with
// its own orientation predicates and constructs crossing points rounded to doubles, as the
// paper did (double, interval, adaptive, cgal). [MK89 §3.3]
// Preconditions: finite double input. Decisions on rounded crossings (output assembly only)
// are the predicates' decisions on the rounded coordinates.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "arithmetic/along.hpp"
#include "arithmetic/formulas.hpp"
#include "kernel/kernel.hpp"

namespace mk {

// Predicates supplies `static constexpr std::string_view name` (the kernel's name) and the
// signs (+1, 0, -1) of orient2d and orient_vectors on doubles. Coordinate comparisons of
// doubles are exact in every kernel, so they are written here once.
template <class Predicates>
struct RoundedCrossingKernel {
  using Point = mk::Point;
  using Vertex = mk::Point;
  static constexpr std::string_view name = Predicates::name;
  static constexpr bool is_exact = false;

  static Point point(const mk::Point& p) { return p; }
  static Sign compare_x(const Point& a, const Point& b) { return a.x < b.x ? Sign::negative : (b.x < a.x ? Sign::positive : Sign::zero); }
  static Sign compare_y(const Point& a, const Point& b) { return a.y < b.y ? Sign::negative : (b.y < a.y ? Sign::positive : Sign::zero); }
  static Sign orient2d(const Point& a, const Point& b, const Point& c) {
    return static_cast<Sign>(Predicates::orient2d(a.x, a.y, b.x, b.y, c.x, c.y));
  }
  static Sign orient_vectors(const Point& p1, const Point& q1, const Point& p2, const Point& q2) {
    return static_cast<Sign>(Predicates::orient_vectors(p1.x, p1.y, q1.x, q1.y, p2.x, p2.y, q2.x, q2.y));
  }
  static Vertex vertex(const Point& p) { return p; }
  static Vertex crossing(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
    Vertex v;
    formula::line_crossing<double>(a0.x, a0.y, a1.x, a1.y, b0.x, b0.y, b1.x, b1.y, v.x, v.y);
    return v;
  }
  static Sign compare_vertices(const Vertex& a, const Vertex& b) {
    const Sign s = compare_x(a, b);
    return s != Sign::zero ? s : compare_y(a, b);
  }
  static Sign compare_along(const Point& s, const Point& d, const Vertex& u, const Vertex& v) {
    return compare_along_lexicographic<RoundedCrossingKernel>(s, d, u, v);
  }
  static Sign orient_vertices(const Vertex& a, const Vertex& b, const Vertex& c) { return orient2d(a, b, c); }
  static mk::Point approx(const Vertex& v) { return v; }
  static std::array<std::string, 2> exact_coordinates(const Vertex&) { return {}; }
};

}  // namespace mk
