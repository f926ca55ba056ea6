// DoubleKernel: plain floating point everywhere; crossing points rounded. The naive baseline:
// its failures are data for the experiments and are never patched in the core.
// [MK89 §3.3] (the paper's warning about ordinary floating point)
// Preconditions: finite double input.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "kernel/kernel.hpp"
#include "arithmetic/along.hpp"
#include "arithmetic/formulas.hpp"

namespace mk {

struct DoubleKernel {
  using Point = mk::Point;
  using Vertex = mk::Point;
  static constexpr std::string_view name = "double";
  static constexpr bool is_exact = false;

  static Point point(const mk::Point& p) { return p; }
  static Sign compare_x(const Point& a, const Point& b) { return sign_of(a.x - b.x); }
  static Sign compare_y(const Point& a, const Point& b) { return sign_of(a.y - b.y); }
  static Sign orient2d(const Point& a, const Point& b, const Point& c) {
    return sign_of(formula::orient2d(a.x, a.y, b.x, b.y, c.x, c.y));
  }
  static Sign orient_vectors(const Point& p1, const Point& q1, const Point& p2, const Point& q2) {
    return sign_of(formula::cross_of_differences(p1.x, p1.y, q1.x, q1.y, p2.x, p2.y, q2.x, q2.y));
  }
  static Vertex vertex(const Point& p) { return p; }
  static Vertex crossing(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
    Vertex v;
    formula::line_crossing<double>(a0.x, a0.y, a1.x, a1.y, b0.x, b0.y, b1.x, b1.y, v.x, v.y);
    return v;
  }
  static Sign compare_vertices(const Vertex& a, const Vertex& b) {
    return a.x != b.x ? sign_of(a.x - b.x) : sign_of(a.y - b.y);
  }
  static Sign compare_along(const Point& s, const Point& d, const Vertex& u, const Vertex& v) {
    return compare_along_lexicographic<DoubleKernel>(s, d, u, v);
  }
  static Sign orient_vertices(const Vertex& a, const Vertex& b, const Vertex& c) { return orient2d(a, b, c); }
  static mk::Point approx(const Vertex& v) { return v; }
  static std::array<std::string, 2> exact_coordinates(const Vertex&) { return {}; }
};

}  // namespace mk
