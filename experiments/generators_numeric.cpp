// Near-degenerate inputs in doubles, where rounded arithmetic decides wrongly: rotated
// (exact degeneracies rotated so that rounding breaks them), magnitude (the same configurations
// at 10^e, where products underflow or overflow), ulp_perturbed (a vertex k ulps off an edge)
// and kettner_grid (the orient2d grids of Kettner et al. as polygon pairs).
// [MK89 §3.3] (numerical accuracy) [KMPSY08 §4] (classroom examples)
// Preconditions: ulp_perturbed's k and kettner_grid's i, j are small (|k| <= 255, i, j < 256).
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "experiments/generator_util.hpp"
#include "experiments/generators.hpp"

namespace mk::experiments {

using detail::finish;
using detail::variant_index;

namespace {

double step_ulps(double x, std::int64_t k) {
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

}  // namespace

PolygonPair magnitude(const CaseSpec& spec);

namespace {

// The case of the exactly degenerate lattice generator that the variant of a generator
// built on them (rotated, magnitude) names; its own variant and seed are drawn from rng.
PolygonPair lattice_case(const CaseSpec& spec, std::mt19937_64& rng) {
  const Generator& base = find_generator(spec.variant);
  if (base.make == nullptr || base.make == &rotated || base.make == &magnitude || spec.variant == "blob" ||
      spec.variant == "star" || spec.variant == "kettner_grid" || spec.variant == "ulp_perturbed") {
    throw std::invalid_argument("generator " + spec.generator + ": '" + spec.variant + "' is not a lattice generator");
  }
  CaseSpec inner{spec.variant,
                 std::string(base.variants[static_cast<std::size_t>(
                     uniform(rng, 0, static_cast<std::int64_t>(base.variants.size()) - 1))]),
                 {},
                 rng()};
  return base.make(inner);
}

}  // namespace

PolygonPair rotated(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  PolygonPair p = lattice_case(spec, rng);
  // One rotation for both polygons: a point shared by A and B stays shared (the same double
  // operations on the same input), but points on a common line generally leave it.
  const double angle = 6.283185307179586 * uniform01(rng);
  const double c = std::cos(angle), s = std::sin(angle);
  for (Polygon* poly : {&p.a, &p.b}) {
    for (auto& ring : poly->rings) {
      for (auto& v : ring) v = {c * v.x - s * v.y, s * v.x + c * v.y};
    }
  }
  return p;
}

PolygonPair magnitude(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::int64_t e = spec.param("e", 0);
  if (e < -300 || e > 300) throw std::invalid_argument("generator magnitude: e must be in -300..300");
  PolygonPair p = lattice_case(spec, rng);
  // Every coordinate times the double nearest 10^e, rounded: a point shared by A and B stays
  // shared, points on a common line may leave it, and the coordinates' products (every
  // orientation test's) underflow below about 1e-154 and overflow above about 1e154.
  const double factor = std::strtod(("1e" + std::to_string(e)).c_str(), nullptr);
  for (Polygon* poly : {&p.a, &p.b}) {
    for (auto& ring : poly->rings) {
      for (auto& v : ring) v = {v.x * factor, v.y * factor};
    }
  }
  return p;
}

PolygonPair ulp_perturbed(const CaseSpec& spec) {
  auto rng = case_rng(spec);
  const std::size_t v = variant_index(spec, {"outside_triangle", "crossing_triangle"});
  const std::int64_t k = spec.param("k", 0);
  // vertex_on_edge with a slanted edge: A convex, B a triangle with its apex on A's edge
  // pq (exactly, on the lattice), then the apex moved k ulps in x or y (the seed decides).
  // k = 0 is the exact degeneracy; the sign of k picks the side.
  IRing a;
  std::size_t i = 0;
  const std::int64_t scale = uniform(rng, 2, 7);
  for (Attempts t("ulp_perturbed: slanted edge");; t.next()) {
    a = scaled(random_convex(rng, {0, 0}, uniform(rng, 5, 40), static_cast<int>(uniform(rng, 3, 8))), scale);
    i = static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(a.size()) - 1));
    const IPoint d = a[(i + 1) % a.size()] - a[i];
    if (d.x != 0 && d.y != 0) break;  // a slanted edge, so the apex's ulp moves leave it
  }
  const IPoint p = a[i], q = a[(i + 1) % a.size()];
  const IPoint apex = p + uniform(rng, 1, scale - 1) * IPoint{(q.x - p.x) / scale, (q.y - p.y) / scale};
  const std::int64_t reach = 5 + std::max(std::abs(q.x - p.x), std::abs(q.y - p.y));
  IPoint q1, q2;
  Attempts t("ulp_perturbed: triangle");
  do {
    t.next();
    q1 = random_point_left_of(rng, q, p, apex, reach);  // outside A
    q2 = v == 0 ? random_point_left_of(rng, q, p, apex, reach) : random_point_left_of(rng, p, q, apex, reach);
  } while (orient(apex, q1, q2) == 0 || is_on_ring(a, q2));
  PolygonPair out = finish(rng, {{a}, {{apex, q1, q2}}});
  // finish() moved every point exactly; find the apex again (it is B's only vertex on A's
  // boundary) and move it.
  const bool along_x = uniform(rng, 0, 1) == 0;
  Ring& tri = out.b.rings[0];
  const auto on_a = [&](const Point& pt) {
    const Ring& ra = out.a.rings[0];
    for (std::size_t j = 0; j < ra.size(); ++j) {
      const Point& e0 = ra[j];
      const Point& e1 = ra[(j + 1) % ra.size()];
      // Exact on the lattice: coordinates are small integers.
      if ((e1.x - e0.x) * (pt.y - e0.y) - (e1.y - e0.y) * (pt.x - e0.x) == 0 && std::min(e0.x, e1.x) <= pt.x &&
          pt.x <= std::max(e0.x, e1.x) && std::min(e0.y, e1.y) <= pt.y && pt.y <= std::max(e0.y, e1.y)) {
        return true;
      }
    }
    return false;
  };
  for (auto& pt : tri) {
    if (!on_a(pt)) continue;
    if (along_x) pt.x = step_ulps(pt.x, k);
    else pt.y = step_ulps(pt.y, k);
  }
  return out;
}

PolygonPair kettner_grid(const CaseSpec& spec) {
  const std::size_t v = variant_index(spec, {"shared_edge_a", "shared_edge_b", "chain_a"});
  const std::int64_t i = spec.param("i", 0), j = spec.param("j", 0);
  if (i < 0 || j < 0 || i > 255 || j > 255) throw std::invalid_argument("generator kettner_grid: i, j in 0..255");
  // [KMPSY08 §4]: orient2d(p', q, r) for p' = p + (i ulp, j ulp) near the line qr. Grid a
  // has p = (0.5, 0.5), q = (12, 12), r = (24, 24); grid b the nearly collinear triple of
  // the same paper.
  struct Triple {
    Point p, q, r;
  };
  const Triple a{{0.5, 0.5}, {12, 12}, {24, 24}};
  const Triple b{{0.50000000000002531, 0.5000000000000171},
                 {17.300000000000001, 17.300000000000001},
                 {24.00000000000005, 24.0000000000000517765}};
  const Triple& t = v == 1 ? b : a;
  const Point p{step_ulps(t.p.x, i), step_ulps(t.p.y, j)};
  PolygonPair out;
  if (v <= 1) {
    // Two triangles sharing the edge qr: A with a clear apex above the line, B the sliver
    // with apex p', whose side of qr is exactly orient2d(p', q, r).
    out.a.rings = {{t.q, t.r, {t.q.x, t.r.y}}};
    out.b.rings = {{t.r, t.q, p}};
  } else {
    // A chain through q: A's edge p'q and B's edge qr nearly continue each other, so the
    // angle at the shared vertex q is decided by the same orient2d.
    out.a.rings = {{p, t.q, {t.p.x, t.q.y}}};
    out.b.rings = {{t.q, t.r, {t.r.x, t.q.y}}};
  }
  return out;
}

}  // namespace mk::experiments
