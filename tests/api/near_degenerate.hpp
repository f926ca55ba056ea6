// Near-degenerate triangle pairs for the rounding tests: the cases where rounding an exact
// result to the nearest doubles breaks its validity (crossing points a few ulps apart,
// slivers a few ulps wide). Written for the tests; seeded.
// [BRIEF §6a] (output validity) [Ho99] (why rounding breaks it)
// Preconditions: none; every pair is in mkbool's input domain (triangles do not cross
// themselves).
#pragma once

#include <cmath>
#include <random>

#include "core/polygon.hpp"

namespace mk::test {

struct TrianglePair {
  Polygon a;
  Polygon b;
};

// Pair `index` of the family: A a random triangle in [0, scale)^2; B's vertices on A's
// edges (as rounded), each moved 0 to 3 ulps along x, in the order that makes B cross A's
// edges near its own vertices (variant 0), or B sharing A's first vertex with its other
// vertices a few ulps off A's edges from that vertex (variant 1).
inline TrianglePair near_degenerate_pair(std::mt19937_64& rng, int variant, double scale = 1.0) {
  std::uniform_real_distribution<double> u(0, scale);
  const auto jitter = [&](double v) {
    const int steps = static_cast<int>(rng() % 4);
    const double toward = (rng() & 1) ? 2 * scale + 1 : -2 * scale - 1;
    for (int s = 0; s < steps; ++s) v = std::nextafter(v, toward);
    return v;
  };
  Ring a{{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
  Ring b;
  if (variant == 0) {
    for (int k = 0; k < 3; ++k) {
      const Point p = a[static_cast<std::size_t>(k)], q = a[static_cast<std::size_t>((k + 1) % 3)];
      const double t = std::uniform_real_distribution<double>(0, 1)(rng);
      b.push_back({jitter(p.x + t * (q.x - p.x)), p.y + t * (q.y - p.y)});
    }
    std::swap(b[1], b[2]);
  } else {
    const double t1 = std::uniform_real_distribution<double>(0.2, 1.5)(rng);
    const double t2 = std::uniform_real_distribution<double>(0.2, 1.5)(rng);
    b.push_back(a[0]);
    b.push_back({jitter(a[0].x + t1 * (a[1].x - a[0].x)), a[0].y + t1 * (a[1].y - a[0].y)});
    b.push_back({jitter(a[0].x + t2 * (a[2].x - a[0].x)), a[0].y + t2 * (a[2].y - a[0].y)});
  }
  return {Polygon{{a}}, Polygon{{b}}};
}

}  // namespace mk::test
