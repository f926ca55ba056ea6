// CgalKernel: CGAL's filtered predicates (Exact_predicates_inexact_constructions_kernel) as
// the external baseline; crossing points rounded to doubles. [MK89 §3.3]
// Preconditions: finite double input; built only when CGAL is found (MK_WITH_CGAL).
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

#include <array>
#include <string>
#include <string_view>

#include "kernel/kernel.hpp"
#include "arithmetic/along.hpp"
#include "arithmetic/formulas.hpp"

namespace mk {

struct CgalKernel {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = mk::Point;
  using Vertex = mk::Point;
  static constexpr std::string_view name = "cgal";
  static constexpr bool is_exact = false;

  static Epick::Point_2 p2(const Point& p) { return {p.x, p.y}; }
  // CGAL's Orientation and Comparison_result are both CGAL::Sign.
  static Sign from(CGAL::Sign s) { return s == CGAL::POSITIVE ? Sign::positive : (s == CGAL::NEGATIVE ? Sign::negative : Sign::zero); }

  static Point point(const mk::Point& p) { return p; }
  static Sign compare_x(const Point& a, const Point& b) { return from(CGAL::compare_x(p2(a), p2(b))); }
  static Sign compare_y(const Point& a, const Point& b) { return from(CGAL::compare_y(p2(a), p2(b))); }
  static Sign orient2d(const Point& a, const Point& b, const Point& c) { return from(CGAL::orientation(p2(a), p2(b), p2(c))); }
  // (q1 - p1) x (q2 - p2) by Epick's filtered vector orientation when the four differences
  // are exact doubles (Knuth's two-sum error is zero), else with CGAL's exact number type.
  static bool exact_difference(double a, double b, double& d) {
    d = a - b;
    const double bv = a - d;
    const double av = d + bv;
    return (a - av) + (bv - b) == 0.0 && std::isfinite(d);
  }
  static Sign orient_vectors(const Point& p1, const Point& q1, const Point& p2_, const Point& q2) {
    double x1, y1, x2, y2;
    if (exact_difference(q1.x, p1.x, x1) && exact_difference(q1.y, p1.y, y1) && exact_difference(q2.x, p2_.x, x2) &&
        exact_difference(q2.y, p2_.y, y2)) {
      return from(CGAL::orientation(Epick::Vector_2(x1, y1), Epick::Vector_2(x2, y2)));
    }
    using ET = CGAL::Exact_predicates_exact_constructions_kernel::FT;
    const ET d = (ET(q1.x) - ET(p1.x)) * (ET(q2.y) - ET(p2_.y)) - (ET(q1.y) - ET(p1.y)) * (ET(q2.x) - ET(p2_.x));
    return from(CGAL::compare(d, ET(0)));
  }
  static Vertex vertex(const Point& p) { return p; }
  static Vertex crossing(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
    Vertex v;
    formula::line_crossing<double>(a0.x, a0.y, a1.x, a1.y, b0.x, b0.y, b1.x, b1.y, v.x, v.y);
    return v;
  }
  static Sign compare_vertices(const Vertex& a, const Vertex& b) { return from(CGAL::compare_xy(p2(a), p2(b))); }
  static Sign compare_along(const Point& s, const Point& d, const Vertex& u, const Vertex& v) {
    return compare_along_lexicographic<CgalKernel>(s, d, u, v);
  }
  static Sign orient_vertices(const Vertex& a, const Vertex& b, const Vertex& c) { return orient2d(a, b, c); }
  static mk::Point approx(const Vertex& v) { return v; }
  static std::array<std::string, 2> exact_coordinates(const Vertex&) { return {}; }
};

}  // namespace mk
