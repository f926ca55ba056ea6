// Inputs shared by the tests of the rounded output's validity (rounded_validity_test,
// rounding_boxes_test): near-degenerate random triangles, and a result's cycles with every
// vertex rounded to its nearest double. [MK89 §3.3] (rounded output)
// Preconditions: none.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/boolean_op.hpp"

namespace mk::test {

// Triangles of nearly collinear points a few ulps apart (whose crossings often round onto
// each other's edges) and plain random triangles.
inline Polygon random_triangle(std::mt19937_64& rng, bool near_degenerate) {
  std::uniform_real_distribution<double> u(-1, 1);
  Polygon p;
  if (!near_degenerate) {
    p.rings.push_back({{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}});
    return p;
  }
  const double x0 = u(rng), y0 = u(rng);
  const double dx = u(rng), dy = u(rng);
  const auto ulps = [&](double v) { return std::nextafter(v, v + static_cast<double>(rng() % 7) - 3); };
  p.rings.push_back({{x0, y0}, {ulps(x0 + dx), ulps(y0 + dy)}, {x0 + 0.5 * dx + 1e-15 * u(rng), y0 + 0.5 * dy}});
  return p;
}

// The result's cycles, every vertex rounded to its nearest double.
inline std::vector<std::vector<Point>> round_result(const BooleanResult<ExactKernel>& r) {
  std::vector<std::vector<Point>> out;
  for (const auto& c : r.cycles) {
    out.emplace_back();
    for (const int id : c.vertices) out.back().push_back(ExactKernel::approx(r.vertex(id)));
  }
  return out;
}

}  // namespace mk::test
