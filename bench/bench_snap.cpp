// The cost of snap rounding at scale (issue 12's bound: O((n + k + h) log n) for n edges,
// k crossings and h edge-hot-pixel incidences): BM_SnapRounding/<workload>/<n> runs the
// exact kernel's intersection and then certified rounding onto a user grid, which always
// snap-rounds, timing the snap rounding alone (hot pixels, the edges' paths through them,
// iterated rounds, the rebuild into polygons and its exact validity check).
// [Ho99] [HP02] [BHO07] [BRIEF §6a]
// Preconditions: built in Release.
//
// Counters: op_s (the operation), snap_s (certified rounding on the grid), snap_ratio
// (snap_s / op_s), hot_pixels, incidences (edge-pixel incidences besides the edges' ends),
// rounds (iterated rounds), vertices_out; time is snap_s.
#include <benchmark/benchmark.h>

#include <chrono>
#include <optional>
#include <string>

#include "api/certified_rounding.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/snap_grid.hpp"
#include "bench/workloads.hpp"
#include "core/boolean_op.hpp"
#include "core/to_output.hpp"

namespace mk::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// grid: the spacing as text (an exact power of two here, so that grid points are doubles).
void BM_SnapRounding(benchmark::State& state, WorkloadKind kind, const char* grid) {
  const Workload w = make_workload(kind, static_cast<std::size_t>(state.range(0)));
  const SnapGrid g = SnapGrid::parse(grid);
  Options opt;
  opt.op = Operation::intersection;
  double op = 0, snap = 0;
  RoundingReport report;
  std::size_t vertices_out = 0;
  for (auto _ : state) {
    auto t = Clock::now();
    const BooleanResult<ExactKernel> r = boolean_op<ExactKernel>(w.a, w.b, opt);
    op += seconds_since(t);
    Output out = to_output<ExactKernel, ExactKernel>(r, false);
    t = Clock::now();
    certify_rounding(r, out, RoundingMode::certified, std::optional<SnapGrid>(g));
    const double s = seconds_since(t);
    snap += s;
    state.SetIterationTime(s);
    if (!out.rounding.snapped || !out.rounding.valid) state.SkipWithError("the snap rounding was not written valid");
    report = out.rounding;
    vertices_out = r.stats.vertices_out;
  }
  const double it = static_cast<double>(state.iterations());
  state.counters["op_s"] = op / it;
  state.counters["snap_s"] = snap / it;
  state.counters["snap_ratio"] = snap / op;
  state.counters["hot_pixels"] = static_cast<double>(report.hot_pixels);
  state.counters["incidences"] = static_cast<double>(report.incidences);
  state.counters["rounds"] = report.rounds;
  state.counters["vertices_out"] = static_cast<double>(vertices_out);
}

// blob: coordinates up to about 130, smooth curves (few incidences); star: about n^2 / 400
// crossings, many of them close together (incidences grow with the grid step).
BENCHMARK_CAPTURE(BM_SnapRounding, blob, WorkloadKind::blob, "1/1024")
    ->RangeMultiplier(10)->Range(1000, 1000000)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SnapRounding, star, WorkloadKind::star, "1/1024")
    ->RangeMultiplier(10)->Range(100, 10000)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mk::bench

BENCHMARK_MAIN();
