// Benchmark workloads: the generators of workloads.hpp.
// [BRIEF §6] (blob, star)
// Preconditions: see workloads.hpp.
#include "bench/workloads.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mk::bench {

namespace {

constexpr Point centre_a{0, 0};
constexpr Point centre_b{30, 10};

// SplitMix64: a generator whose output is fixed by the seed on every platform, unlike the
// distributions of <random>, so a workload is the same wherever it is rebuilt.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

Ring blob_ring(std::size_t n, Point c, double phase) {
  Ring r;
  r.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const double radius = 100 * (1 + 0.1 * std::sin(5 * t + phase));
    r.push_back({c.x + radius * std::cos(t), c.y + radius * std::sin(t)});
  }
  return r;
}

Ring star_ring(std::size_t n, Point c, SplitMix64& rng) {
  std::vector<double> angles(n);
  for (auto& a : angles) a = 2 * std::numbers::pi * rng.uniform();
  std::sort(angles.begin(), angles.end());
  // Equal angles would put three vertices on one ray; with 53-bit angles this never
  // happens at benchmark sizes, but drop them rather than emit a degenerate ring.
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  Ring r;
  r.reserve(angles.size());
  for (const double a : angles) {
    const double radius = 50 + 50 * rng.uniform();
    r.push_back({c.x + radius * std::cos(a), c.y + radius * std::sin(a)});
  }
  return r;
}

// Counterclockwise square [x0, x1] x [y0, y1].
Ring square(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// A square annulus around the origin: counterclockwise outer square, clockwise hole.
OgcPolygon annulus(double inner, double outer) {
  Ring hole = square(-inner, -inner, inner, inner);
  std::reverse(hole.begin(), hole.end());
  return {square(-outer, -outer, outer, outer), {hole}};
}

MultiPolygon checkerboard_grid(std::size_t n, double dx) {
  // The dark cells (i + j even) of a side x side grid, row by row, until n are placed.
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(2.0 * static_cast<double>(n))));
  MultiPolygon mp;
  mp.reserve(n);
  for (std::size_t j = 0; j < side + 1 && mp.size() < n; ++j) {
    for (std::size_t i = j % 2; i < side && mp.size() < n; i += 2) {
      const double x = static_cast<double>(i) + dx;
      const double y = static_cast<double>(j);
      mp.push_back({square(x, y, x + 1, y + 1), {}});
    }
  }
  return mp;
}

Workload finish(WorkloadKind kind, std::size_t n, std::uint64_t seed, MultiPolygon a, MultiPolygon b) {
  Workload w;
  w.kind = kind;
  w.n = n;
  w.seed = seed;
  w.a = to_polygon(a);
  w.b = to_polygon(b);
  w.a_ogc = std::move(a);
  w.b_ogc = std::move(b);
  return w;
}

}  // namespace

std::size_t Workload::vertices() const {
  std::size_t v = 0;
  for (const auto* p : {&a, &b}) {
    for (const auto& r : p->rings) v += r.size();
  }
  return v;
}

Workload blob(std::size_t n, std::uint64_t seed) {
  const double phase = static_cast<double>(seed);
  return finish(WorkloadKind::blob, n, seed, {{blob_ring(n, centre_a, phase), {}}},
                {{blob_ring(n, centre_b, phase), {}}});
}

Workload star(std::size_t n, std::uint64_t seed) {
  SplitMix64 rng(seed);
  Ring ra = star_ring(n, centre_a, rng);
  Ring rb = star_ring(n, centre_b, rng);
  return finish(WorkloadKind::star, n, seed, {{std::move(ra), {}}}, {{std::move(rb), {}}});
}

Workload checkerboard(std::size_t n) {
  return finish(WorkloadKind::checkerboard, n, 0, checkerboard_grid(n, 0), checkerboard_grid(n, 0.5));
}

Workload stripes(std::size_t n) {
  const double width = 4 * static_cast<double>(n);
  MultiPolygon a, b;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = 4 * static_cast<double>(i);
    a.push_back({square(0, y, width, y + 1), {}});
    b.push_back({square(0, y + 2, width, y + 3), {}});
  }
  return finish(WorkloadKind::stripes, n, 0, std::move(a), std::move(b));
}

Workload checkerboard_shared(std::size_t n) {
  // The light cells (i + j odd) of the grid of checkerboard_grid(n, 0), n of them.
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(2.0 * static_cast<double>(n))));
  MultiPolygon light;
  for (std::size_t j = 0; j < side + 1 && light.size() < n; ++j) {
    for (std::size_t i = 1 - j % 2; i < side && light.size() < n; i += 2) {
      const double x = static_cast<double>(i);
      const double y = static_cast<double>(j);
      light.push_back({square(x, y, x + 1, y + 1), {}});
    }
  }
  return finish(WorkloadKind::checkerboard_shared, n, 0, checkerboard_grid(n, 0), std::move(light));
}

Workload checkerboard_offset(std::size_t n) {
  MultiPolygon b = checkerboard_grid(n, 0.5);
  for (OgcPolygon& p : b) {
    for (Point& q : p.shell) q.y += 0.5;
  }
  return finish(WorkloadKind::checkerboard_offset, n, 0, checkerboard_grid(n, 0), std::move(b));
}

Workload many_holes(std::size_t n) {
  const auto k = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const auto plate = [&](double d) {
    const double side = static_cast<double>(k);
    OgcPolygon p{square(d, d, side + d, side + d), {}};
    p.holes.reserve(k * k);
    for (std::size_t j = 0; j < k; ++j) {
      for (std::size_t i = 0; i < k; ++i) {
        const double x = static_cast<double>(i) + d;
        const double y = static_cast<double>(j) + d;
        Ring hole = square(x + 0.2, y + 0.2, x + 0.6, y + 0.6);
        std::reverse(hole.begin(), hole.end());
        p.holes.push_back(std::move(hole));
      }
    }
    return MultiPolygon{std::move(p)};
  };
  return finish(WorkloadKind::many_holes, n, 0, plate(0), plate(0.2));
}

Workload long_spikes(std::size_t n) {
  // A: a saw over [0, w] x [0, h] whose teeth alternate between x = 0 and x = w, closed along
  // x = -1; B: a smooth curve inside the box that every tooth crosses.
  const std::size_t teeth = std::max<std::size_t>(1, n / 4);
  const double w = 2 * static_cast<double>(teeth);
  const double h = 2 * static_cast<double>(teeth);
  Ring saw;
  saw.reserve(2 * teeth + 3);
  saw.push_back({-1, 0});
  for (std::size_t i = 0; i < teeth; ++i) {
    saw.push_back({0, 2 * static_cast<double>(i)});
    saw.push_back({w, 2 * static_cast<double>(i) + 1});
  }
  saw.push_back({0, h});
  saw.push_back({-1, h});
  const std::size_t m = std::max<std::size_t>(3, n / 2);
  Ring curve;
  curve.reserve(m);
  for (std::size_t i = 0; i < m; ++i) {
    const double t = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(m);
    const double r = 0.4 * (1 + 0.1 * std::sin(5 * t));
    curve.push_back({w / 2 + r * w * std::cos(t), h / 2 + r * h * std::sin(t)});
  }
  return finish(WorkloadKind::long_spikes, n, 0, {{std::move(saw), {}}}, {{std::move(curve), {}}});
}

Workload nested_squares(std::size_t n) {
  MultiPolygon a, b;
  for (std::size_t k = 0; k < n; ++k) {
    const double s = 4 * static_cast<double>(k);
    a.push_back(annulus(s + 1, s + 3));
    b.push_back(annulus(s + 2, s + 5));
  }
  return finish(WorkloadKind::nested_squares, n, 0, std::move(a), std::move(b));
}

Workload nested_wavy_rings(std::size_t n) {
  constexpr int kPoints = 64;
  const auto ring = [](double cx, double cy, double r, double phase, bool counterclockwise) {
    Ring out;
    out.reserve(kPoints);
    for (int i = 0; i < kPoints; ++i) {
      const double t = 2 * std::numbers::pi * i / kPoints;
      const double radius = r + 0.1 * std::sin(7 * t + phase);
      out.push_back({cx + radius * std::cos(t), cy + radius * std::sin(t)});
    }
    if (!counterclockwise) std::reverse(out.begin(), out.end());
    return out;
  };
  MultiPolygon a, b;
  a.reserve(n);
  b.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double r = 2 * static_cast<double>(k);
    const double phase = static_cast<double>(k);
    a.push_back({ring(0, 0, r + 1.6, phase, true), {ring(0, 0, r + 1.0, phase, false)}});
    b.push_back({ring(0.7, 0.3, r + 1.6, phase + 1, true), {ring(0.7, 0.3, r + 1.0, phase + 1, false)}});
  }
  return finish(WorkloadKind::nested_wavy_rings, n, 0, std::move(a), std::move(b));
}

Workload make_workload(WorkloadKind kind, std::size_t n) {
  switch (kind) {
    case WorkloadKind::blob: return blob(n);
    case WorkloadKind::star: return star(n);
    case WorkloadKind::stripes: return stripes(n);
    case WorkloadKind::checkerboard: return checkerboard(n);
    case WorkloadKind::checkerboard_shared: return checkerboard_shared(n);
    case WorkloadKind::checkerboard_offset: return checkerboard_offset(n);
    case WorkloadKind::many_holes: return many_holes(n);
    case WorkloadKind::long_spikes: return long_spikes(n);
    case WorkloadKind::nested_squares: return nested_squares(n);
    case WorkloadKind::nested_wavy_rings: return nested_wavy_rings(n);
  }
  throw std::invalid_argument("unknown workload");
}

}  // namespace mk::bench
