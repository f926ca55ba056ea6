// RationalKernel: exact rationals for every predicate and exact crossing points; the ground
// truth. Written once over the number type (BasicRationalKernel<Q>); RationalKernel is GMP's
// mpq_class, rational_mp_kernels.hpp adds Boost.Multiprecision's types. [MK89 §3.3]
// (exact decisions)
// Preconditions: input coordinates are finite doubles or exact rationals; Q has a
// RationalNumber specialisation.
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

// What the kernel needs of a rational number type Q beyond + - * / and comparison:
//   kernel_name                  the kernel's name
//   from_double(double)          the exact value of a finite double
//   compare(a, b), sign(a)       -1, 0 or +1
//   canonicalize(a)              reduce a fraction that arithmetic left unreduced
//   text(a)                      "p/q" reduced, or "p": mpq_get_str's form
//   nearest(a)                   the nearest double, ties to even (nearest_double, MPFR)
template <class Q>
struct RationalNumber;

template <>
struct RationalNumber<mpq_class> {
  static constexpr std::string_view kernel_name = "rational";
  static mpq_class from_double(double v) { return mpq_class(v); }  // mpq_set_d: exact
  static int compare(const mpq_class& a, const mpq_class& b) { return cmp(a, b); }
  static int sign(const mpq_class& a) { return sgn(a); }
  static void canonicalize(mpq_class& a) { a.canonicalize(); }
  static std::string text(const mpq_class& a) { return a.get_str(); }
  static double nearest(const mpq_class& a) { return nearest_double(a); }
};

template <class Q>
struct BasicRationalPoint {
  Q x;
  Q y;
  friend bool operator==(const BasicRationalPoint& a, const BasicRationalPoint& b) {
    return a.x == b.x && a.y == b.y;
  }
};

template <class Q>
struct BasicRationalKernel {
  using Number = RationalNumber<Q>;
  using Point = BasicRationalPoint<Q>;
  using Vertex = BasicRationalPoint<Q>;
  static constexpr std::string_view name = Number::kernel_name;
  static constexpr bool is_exact = true;

  static Point point(const mk::Point& p) { return {Number::from_double(p.x), Number::from_double(p.y)}; }
  static Sign compare_x(const Point& a, const Point& b) { return sign_of(Number::compare(a.x, b.x)); }
  static Sign compare_y(const Point& a, const Point& b) { return sign_of(Number::compare(a.y, b.y)); }
  static Sign orient2d(const Point& a, const Point& b, const Point& c) {
    return sign_of(Number::sign(formula::orient2d<Q>(a.x, a.y, b.x, b.y, c.x, c.y)));
  }
  static Sign orient_vectors(const Point& p1, const Point& q1, const Point& p2, const Point& q2) {
    return sign_of(Number::sign(formula::cross_of_differences<Q>(p1.x, p1.y, q1.x, q1.y, p2.x, p2.y, q2.x, q2.y)));
  }
  static Vertex vertex(const Point& p) { return p; }
  static Vertex crossing(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
    Vertex v;
    formula::line_crossing<Q>(a0.x, a0.y, a1.x, a1.y, b0.x, b0.y, b1.x, b1.y, v.x, v.y);
    Number::canonicalize(v.x);
    Number::canonicalize(v.y);
    return v;
  }
  static Sign compare_vertices(const Vertex& a, const Vertex& b) {
    const int c = Number::compare(a.x, b.x);
    return sign_of(c != 0 ? c : Number::compare(a.y, b.y));
  }
  static Sign compare_along(const Point& s, const Point& d, const Vertex& u, const Vertex& v) {
    return compare_along_lexicographic<BasicRationalKernel>(s, d, u, v);
  }
  static Sign orient_vertices(const Vertex& a, const Vertex& b, const Vertex& c) { return orient2d(a, b, c); }
  static mk::Point approx(const Vertex& v) { return {to_nearest(v.x), to_nearest(v.y)}; }
  static std::array<std::string, 2> exact_coordinates(const Vertex& v) { return {Number::text(v.x), Number::text(v.y)}; }

  // The nearest double to a rational, ties to even, +-infinity beyond the double range
  // (MPFR, arithmetic/nearest_double.hpp).
  static double to_nearest(const Q& q) { return Number::nearest(q); }
};

using RationalPoint = BasicRationalPoint<mpq_class>;
using RationalKernel = BasicRationalKernel<mpq_class>;

}  // namespace mk
