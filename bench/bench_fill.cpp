// BM_UnionAll<Library>/<workload>/<n>: the union of many overlapping polygons in one call:
// mkbool's union_all (one arrangement, exact), GEOS's GEOSUnaryUnion_r (floating
// precision), Clipper 6.4 (all paths in one Execute, nonzero) and CGAL's
// Polygon_set_2::join over Epeck (exact, the reference; not on `spread`). BM_SelfCrossing<Library>/
// <rule>/<n>: a random star-shaped ring of n vertices whose angles are jittered by up to
// three steps (so that it crosses itself a few times per vertex), intersected with itself by a fill rule, mkbool against Clipper. Issue 13's speed bars.
// Workloads: `circles`, n random 32-gons of radius 0.5-2 in a 100 x 100 square (seed 1);
// `spread`, the same 32-gons at the density of `circles` at n = 10^4, in a square whose side
// grows as sqrt(n) (crossings grow with n: issue 13's growth from 10^3 to 10^6 vertices in
// all, plotted by bench/plot_fill_growth.py); `grid`, a k x k grid of unit squares sharing
// every edge (n = k^2), the coverage case.
// [BRIEF §6] paper-notes.md deviation 17
// Preconditions: built with GEOS (MK_HAVE_GEOS) and Clipper (MK_HAVE_CLIPPER) when found.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/mkbool.hpp"

#ifdef MK_HAVE_GEOS
#include <geos_c.h>
#endif
#ifdef MK_HAVE_CLIPPER
#include <polyclipping/clipper.hpp>
#endif
#ifdef MK_HAVE_CGAL
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <iterator>
#endif

namespace mk::bench {
namespace {

MultiPolygon circles(int n, double side = 100) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> pos(0, side), rad(0.5, 2);
  MultiPolygon out;
  for (int i = 0; i < n; ++i) {
    const double cx = pos(rng), cy = pos(rng), r = rad(rng);
    Ring ring;
    for (int k = 0; k < 32; ++k) ring.push_back({cx + r * std::cos(2 * M_PI * k / 32), cy + r * std::sin(2 * M_PI * k / 32)});
    out.push_back({ring, {}});
  }
  return out;
}

MultiPolygon grid(int n) {
  const int k = static_cast<int>(std::lround(std::sqrt(n)));
  MultiPolygon out;
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      const double x = i, y = j;
      out.push_back({{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}, {}});
    }
  }
  return out;
}

MultiPolygon workload(const std::string& name, int n) {
  if (name == "spread") return circles(n, 100 * std::sqrt(n / 1e4));
  return name == "circles" ? circles(n) : grid(n);
}

void BM_UnionAllMkbool(benchmark::State& state, const std::string& name) {
  const MultiPolygon parts = workload(name, static_cast<int>(state.range(0)));
  BooleanOptions o;
  o.area = false;
  std::size_t out = 0, crossings = 0;
  for (auto _ : state) {
    const BooleanOutput r = union_all(parts, o);
    out = r.stats.vertices_out;
    crossings = r.stats.crossings;
    benchmark::DoNotOptimize(out);
  }
  state.counters["vertices_out"] = static_cast<double>(out);
  state.counters["crossings"] = static_cast<double>(crossings);
  std::size_t in = 0;
  for (const OgcPolygon& p : parts) in += p.shell.size();
  state.counters["vertices_in"] = static_cast<double>(in);
}

#ifdef MK_HAVE_GEOS
void BM_UnionAllGeos(benchmark::State& state, const std::string& name) {
  const MultiPolygon parts = workload(name, static_cast<int>(state.range(0)));
  GEOSContextHandle_t ctx = GEOS_init_r();
  std::vector<GEOSGeometry*> polys;
  for (const OgcPolygon& p : parts) {
    std::vector<double> xy;
    for (const Point& q : p.shell) xy.insert(xy.end(), {q.x, q.y});
    xy.insert(xy.end(), {p.shell.front().x, p.shell.front().y});
    GEOSCoordSequence* seq = GEOSCoordSeq_copyFromBuffer_r(ctx, xy.data(), static_cast<unsigned>(p.shell.size() + 1), 0, 0);
    polys.push_back(GEOSGeom_createPolygon_r(ctx, GEOSGeom_createLinearRing_r(ctx, seq), nullptr, 0));
  }
  GEOSGeometry* all = GEOSGeom_createCollection_r(ctx, GEOS_GEOMETRYCOLLECTION, polys.data(), static_cast<unsigned>(polys.size()));
  double area = 0;
  for (auto _ : state) {
    GEOSGeometry* u = GEOSUnaryUnion_r(ctx, all);
    if (u == nullptr) throw std::runtime_error("GEOSUnaryUnion failed");
    GEOSArea_r(ctx, u, &area);
    GEOSGeom_destroy_r(ctx, u);
  }
  state.counters["area"] = area;
  GEOSGeom_destroy_r(ctx, all);
  GEOS_finish_r(ctx);
}
#endif

#ifdef MK_HAVE_CGAL
void BM_UnionAllCgal(benchmark::State& state, const std::string& name) {
  using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
  const MultiPolygon parts = workload(name, static_cast<int>(state.range(0)));
  std::vector<CGAL::Polygon_2<Epeck>> polygons;
  for (const OgcPolygon& p : parts) {
    CGAL::Polygon_2<Epeck> q;
    for (const Point& v : p.shell) q.push_back(Epeck::Point_2(v.x, v.y));
    if (q.is_clockwise_oriented()) q.reverse_orientation();
    polygons.push_back(std::move(q));
  }
  double area = 0;
  for (auto _ : state) {
    CGAL::Polygon_set_2<Epeck> set;
    set.join(polygons.begin(), polygons.end());
    std::vector<CGAL::Polygon_with_holes_2<Epeck>> out;
    set.polygons_with_holes(std::back_inserter(out));
    Epeck::FT a = 0;
    for (const auto& p : out) {
      a += p.outer_boundary().area();
      for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += h->area();  // clockwise: negative
    }
    area = CGAL::to_double(a);
  }
  state.counters["area"] = area;
}
#endif

#ifdef MK_HAVE_CLIPPER
void BM_UnionAllClipper(benchmark::State& state, const std::string& name) {
  const MultiPolygon parts = workload(name, static_cast<int>(state.range(0)));
  const double scale = std::ldexp(1.0, 22);  // coordinates below 256 (spread at 32,000: 181): within Clipper's loRange
  ClipperLib::Paths paths;
  for (const OgcPolygon& p : parts) {
    ClipperLib::Path path;
    for (const Point& q : p.shell) path.emplace_back(std::llround(q.x * scale), std::llround(q.y * scale));
    paths.push_back(std::move(path));
  }
  std::size_t out = 0;
  for (auto _ : state) {
    ClipperLib::Clipper c;
    c.AddPaths(paths, ClipperLib::ptSubject, true);
    ClipperLib::Paths solution;
    c.Execute(ClipperLib::ctUnion, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    out = 0;
    for (const auto& s : solution) out += s.size();
  }
  state.counters["vertices_out"] = static_cast<double>(out);
}
#endif

Polygon random_self_crossing(int n) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> jitter(-3, 3), radius(50, 100);
  Polygon p;
  p.rings.emplace_back();
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * (i + jitter(rng)) / n;
    const double r = radius(rng);
    p.rings[0].push_back({r * std::cos(t), r * std::sin(t)});
  }
  return p;
}

void BM_SelfCrossingMkbool(benchmark::State& state, FillRule rule) {
  const Polygon a = random_self_crossing(static_cast<int>(state.range(0)));
  BooleanOptions o;
  o.op = Operation::intersection;
  o.fill_rule = rule;
  o.area = false;
  std::size_t out = 0;
  for (auto _ : state) {
    const BooleanOutput r = compute(a, a, o);
    out = r.stats.vertices_out;
    benchmark::DoNotOptimize(out);
  }
  state.counters["vertices_out"] = static_cast<double>(out);
}

#ifdef MK_HAVE_CLIPPER
void BM_SelfCrossingClipper(benchmark::State& state, FillRule rule) {
  const Polygon a = random_self_crossing(static_cast<int>(state.range(0)));
  const double scale = std::ldexp(1.0, 22);  // |coordinates| below 128
  ClipperLib::Path path;
  for (const Point& q : a.rings[0]) path.emplace_back(std::llround(q.x * scale), std::llround(q.y * scale));
  const auto type = rule == FillRule::evenodd ? ClipperLib::pftEvenOdd : ClipperLib::pftNonZero;
  std::size_t out = 0;
  for (auto _ : state) {
    ClipperLib::Clipper c;
    c.AddPath(path, ClipperLib::ptSubject, true);
    c.AddPath(path, ClipperLib::ptClip, true);
    ClipperLib::Paths solution;
    c.Execute(ClipperLib::ctIntersection, solution, type, type);
    out = 0;
    for (const auto& s : solution) out += s.size();
  }
  state.counters["vertices_out"] = static_cast<double>(out);
}
#endif

void register_all() {
  for (const FillRule rule : {FillRule::evenodd, FillRule::nonzero}) {
    const std::string r(fill_rule_name(rule));
    benchmark::RegisterBenchmark(("BM_SelfCrossing<Mkbool>/" + r).c_str(), BM_SelfCrossingMkbool, rule)
        ->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
#ifdef MK_HAVE_CLIPPER
    benchmark::RegisterBenchmark(("BM_SelfCrossing<Clipper>/" + r).c_str(), BM_SelfCrossingClipper, rule)
        ->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif
  }
  for (const std::string w : {"circles", "grid", "spread"}) {
    const std::vector<long> sizes = w == "circles" ? std::vector<long>{1000, 10000}
                                    : w == "spread" ? std::vector<long>{32, 320, 3200, 32000}
                                                    : std::vector<long>{10000};
    for (const long n : sizes) {
      benchmark::RegisterBenchmark(("BM_UnionAll<Mkbool>/" + w).c_str(), BM_UnionAllMkbool, w)
          ->Arg(n)->Unit(benchmark::kMillisecond)->UseRealTime();
#ifdef MK_HAVE_GEOS
      benchmark::RegisterBenchmark(("BM_UnionAll<Geos>/" + w).c_str(), BM_UnionAllGeos, w)
          ->Arg(n)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif
#ifdef MK_HAVE_CLIPPER
      benchmark::RegisterBenchmark(("BM_UnionAll<Clipper>/" + w).c_str(), BM_UnionAllClipper, w)
          ->Arg(n)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif
#ifdef MK_HAVE_CGAL
      if (w != "spread") {
        benchmark::RegisterBenchmark(("BM_UnionAll<Cgal>/" + w).c_str(), BM_UnionAllCgal, w)
            ->Arg(n)->Unit(benchmark::kMillisecond)->UseRealTime();
      }
#endif
    }
  }
}

}  // namespace
}  // namespace mk::bench

int main(int argc, char** argv) {
  mk::bench::register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
