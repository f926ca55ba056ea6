// Random generators: grid_random (random polygons on a small integer grid, dense
// coincidences), and the large workloads blob and star of the performance brief.
// [MK89 §4.2] (complexity in n and the number of crossings k)
// Preconditions: the "n" parameter of blob and star is at least 3.
#include <cmath>
#include <stdexcept>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "experiments/generator_util.hpp"
#include "experiments/generators.hpp"

namespace mk::experiments {

using detail::finish;
using detail::LatticePair;
using detail::variant_index;

PolygonPair grid_random(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"simple", "holes", "hole_type"});
  const std::int64_t grid = spec.param("grid", 8);
  // Stars of at most `grid` cells across, centred in the grid: many shared vertices,
  // vertices on edges and collinear edges happen by chance.
  const auto make = [&] {
    const IPoint c{uniform(rng, 1, grid - 2), uniform(rng, 1, grid - 2)};
    const int rmax = static_cast<int>(std::max<std::int64_t>(2, grid / 2));
    std::vector<IRing> rings{random_star(rng, c, 2, rmax, static_cast<int>(uniform(rng, 3, 10)))};
    if (v == 1) {
      const IRing h = detail::hole_inside(rng, rings[0], c, 1);
      if (!h.empty()) rings.push_back(h);
    }
    return rings;
  };
  LatticePair p{make(), make()};
  if (v == 2) (uniform(rng, 0, 1) == 0 ? p.a_type : p.b_type) = PolygonType::hole;
  return finish(rng, p);
}

namespace {

// Whether the ring of doubles turns left around c at every edge (exactly): then, being
// ordered by angle, it is a simple star-shaped polygon.
bool is_star_around(const Ring& r, Point c) {
  const auto cc = RationalKernel::point(c);
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (RationalKernel::orient2d(cc, RationalKernel::point(r[i]), RationalKernel::point(r[(i + 1) % r.size()])) !=
        Sign::positive) {
      return false;
    }
  }
  return true;
}

std::int64_t vertex_count(const CaseSpec& spec) {
  const std::int64_t n = spec.param("n", 64);
  if (n < 3) throw std::invalid_argument("generator " + spec.generator + ": n must be at least 3");
  return n;
}

}  // namespace

PolygonPair blob(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  variant_index(spec, {"smooth"});
  const std::int64_t n = vertex_count(spec);
  // r(t) = 100 (1 + 0.1 sin(5t + phase)) around the centres (0, 0) and (30, 10), the phase
  // drawn from the seed: two smooth closed curves crossing twice.
  const auto curve = [&](Point c) {
    const double phase = 6.283185307179586 * uniform01(rng);
    Ring r;
    for (std::int64_t i = 0; i < n; ++i) {
      const double t = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
      const double rad = 100 * (1 + 0.1 * std::sin(5 * t + phase));
      r.push_back({c.x + rad * std::cos(t), c.y + rad * std::sin(t)});
    }
    return r;
  };
  PolygonPair p;
  p.a.rings = {curve({0, 0})};
  p.b.rings = {curve({30, 10})};
  return p;
}

PolygonPair star(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  variant_index(spec, {"random"});
  const std::int64_t n = vertex_count(spec);
  // Random angles, radii uniform in [50, 100], centres (0, 0) and (30, 10): about n^2/400
  // crossings. Redrawn until exactly star-shaped (a rounding could fold two close angles).
  const auto make = [&](Point c) {
    for (Attempts t("star");; t.next()) {
      std::vector<double> angles;
      for (std::int64_t i = 0; i < n; ++i) angles.push_back(6.283185307179586 * uniform01(rng));
      std::sort(angles.begin(), angles.end());
      Ring r;
      for (const double t : angles) {
        const double rad = 50 + 50 * uniform01(rng);
        r.push_back({c.x + rad * std::cos(t), c.y + rad * std::sin(t)});
      }
      if (is_star_around(r, c)) return r;
    }
  };
  PolygonPair p;
  p.a.rings = {make({0, 0})};
  p.b.rings = {make({30, 10})};
  return p;
}

}  // namespace mk::experiments
