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

Workload nested_squares(std::size_t n) {
  MultiPolygon a, b;
  for (std::size_t k = 0; k < n; ++k) {
    const double s = 4 * static_cast<double>(k);
    a.push_back(annulus(s + 1, s + 3));
    b.push_back(annulus(s + 2, s + 5));
  }
  return finish(WorkloadKind::nested_squares, n, 0, std::move(a), std::move(b));
}

Workload make_workload(WorkloadKind kind, std::size_t n) {
  switch (kind) {
    case WorkloadKind::blob: return blob(n);
    case WorkloadKind::star: return star(n);
    case WorkloadKind::checkerboard: return checkerboard(n);
    case WorkloadKind::nested_squares: return nested_squares(n);
  }
  throw std::invalid_argument("unknown workload");
}

}  // namespace mk::bench
