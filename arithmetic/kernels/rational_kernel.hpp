// RationalKernel: GMP rationals for every predicate and exact crossing points; the ground truth.
// [MK89 §3.3] (exact decisions) 
// Preconditions: input coordinates are finite doubles or exact rationals.
#pragma once

#include <gmpxx.h>

#include <array>
#include <string>
#include <string_view>

#include "kernel/kernel.hpp"
#include "arithmetic/along.hpp"
#include "arithmetic/nearest_double.hpp"
#include "arithmetic/formulas.hpp"

namespace mk {

struct RationalPoint {
  mpq_class x;
  mpq_class y;
  friend bool operator==(const RationalPoint& a, const RationalPoint& b) {
    return a.x == b.x && a.y == b.y;
  }
};

struct RationalKernel {
  using Point = RationalPoint;
  using Vertex = RationalPoint;
  static constexpr std::string_view name = "rational";
  static constexpr bool is_exact = true;

  static Point point(const mk::Point& p) { return {mpq_class(p.x), mpq_class(p.y)}; }
  static Sign compare_x(const Point& a, const Point& b) { return sign_of(cmp(a.x, b.x)); }
  static Sign compare_y(const Point& a, const Point& b) { return sign_of(cmp(a.y, b.y)); }
  static Sign orient2d(const Point& a, const Point& b, const Point& c) {
    return sign_of(sgn(mpq_class(formula::orient2d(a.x, a.y, b.x, b.y, c.x, c.y))));
  }
  static Sign orient_vectors(const Point& p1, const Point& q1, const Point& p2, const Point& q2) {
    return sign_of(sgn(mpq_class(
        formula::cross_of_differences(p1.x, p1.y, q1.x, q1.y, p2.x, p2.y, q2.x, q2.y))));
  }
  static Vertex vertex(const Point& p) { return p; }
  static Vertex crossing(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
    Vertex v;
    formula::line_crossing<mpq_class>(a0.x, a0.y, a1.x, a1.y, b0.x, b0.y, b1.x, b1.y, v.x, v.y);
    v.x.canonicalize();
    v.y.canonicalize();
    return v;
  }
  static Sign compare_vertices(const Vertex& a, const Vertex& b) {
    const int c = cmp(a.x, b.x);
    return sign_of(c != 0 ? c : cmp(a.y, b.y));
  }
  static Sign compare_along(const Point& s, const Point& d, const Vertex& u, const Vertex& v) {
    return compare_along_lexicographic<RationalKernel>(s, d, u, v);
  }
  static Sign orient_vertices(const Vertex& a, const Vertex& b, const Vertex& c) { return orient2d(a, b, c); }
  static mk::Point approx(const Vertex& v) { return {to_nearest(v.x), to_nearest(v.y)}; }
  static std::array<std::string, 2> exact_coordinates(const Vertex& v) {
    return {v.x.get_str(), v.y.get_str()};
  }

  // The nearest double to a rational, ties to even, +-infinity beyond the double range
  // (MPFR, arithmetic/nearest_double.hpp).
  static double to_nearest(const mpq_class& q) { return nearest_double(q); }
};

}  // namespace mk
