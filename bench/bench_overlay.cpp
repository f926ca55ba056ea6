// The overlay benchmark against peers: BM_Overlay<runner>/<workload>/<op>/<n>, where a
// runner is a peer library (GEOS, BoostGeometry, Clipper, CgalEpeck) or an mkbool kernel
// (mkbool:<name>, every name in mk::kernel_names()), on the same two inputs.
// [BRIEF §6] (workloads, peers, the bar) [MK89 §4.3] (cost of the intersection step)
// Preconditions: built in Release; peers compiled in when found (MK_HAVE_GEOS, ...).
//
// Counters: vertices_in (A and B), vertices_out, crossings (mkbool only: peers do not say),
// area_rel_diff = (area - exact) / |exact| against mkbool's exact area of the same case
// (absolute difference when the exact area is 0). The label names the reference kernel.
// Benchmarks measure speed; the area difference is reported as data, never asserted.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "api/mkbool.hpp"
#include "arithmetic/kernels/double_kernel.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/filtered_kernels.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#ifdef MK_WITH_CGAL
#include "arithmetic/kernels/cgal_kernel.hpp"
#endif
#include "bench/peers/mkbool_area.hpp"
#include "bench/peers/peers.hpp"
#include "bench/workloads.hpp"
#include "core/boolean_op.hpp"
#include "core/to_output.hpp"

namespace mk::bench {

namespace {

// Sizes: vertices per polygon for blob and star, squares per grid for checkerboard, rings
// per polygon for nested squares.
const std::vector<std::pair<WorkloadKind, std::vector<std::size_t>>> kSizes = {
    // Blob 10^7 (2*10^7 input vertices) runs once, intersection only, for the runners of
    // kAtHugeSize: issue 14's "blob 10^7 once".
    {WorkloadKind::blob, {1'000, 10'000, 100'000, 1'000'000, 10'000'000}},
    // n + k, the size the star's time is measured against, reaches 10^6 at n = 20,000
    // (about n^2 / 400 crossings: 10^6 there).
    {WorkloadKind::star, {100, 1'000, 10'000, 20'000}},
    {WorkloadKind::checkerboard, {100, 1'000, 10'000, 100'000}},
    // 16 n input vertices in all: up to 1.6 * 10^6.
    {WorkloadKind::nested_squares, {10, 100, 1'000, 10'000, 100'000}},
    // Issue 14's shapes: each stresses one way for an overlay to turn superlinear.
    {WorkloadKind::stripes, {125, 1'000, 8'000, 125'000}},
    {WorkloadKind::checkerboard_shared, {1'000, 10'000, 100'000}},
    {WorkloadKind::checkerboard_offset, {1'000, 10'000, 100'000}},
    {WorkloadKind::many_holes, {1'000, 10'000, 100'000}},
    {WorkloadKind::long_spikes, {1'000, 10'000, 100'000, 1'000'000}},
    // Contour lines (annuli of two 64-point rings each): 256 n input vertices, up to about
    // 10^6; boxes that overlap without their edges meeting (the red-blue sweep's case).
    {WorkloadKind::nested_wavy_rings, {10, 100, 1'000, 4'000}},
};

// The one size past a workload's regular sizes (blob 10^7): run once, intersection only,
// by these runners; the others stop at the size before.
constexpr std::size_t kHugeSize = 10'000'000;
constexpr std::string_view kAtHugeSize[] = {"mkbool:exact", "GEOS", "BoostGeometry", "Clipper"};

constexpr Operation kOperations[] = {Operation::intersection, Operation::union_, Operation::difference,
                                     Operation::symmetric_difference};

// The default run's length on the project's 2-core machine: bench/README.md, "Limits".
//  - at the largest size of each workload, every operation runs for `exact` and the peers
//    that are not CGAL (kEveryOperationAtLargest); the other runners, slower or research
//    kernels, run the intersection only (the operation of the bar in BRIEF §6);
//  - runners that take minutes at a size are left out there (kSizeLimits);
//  - at the largest sizes every runner is measured once (one iteration, no repetitions),
//    except, on blob 10^6 (the bar's row), the fast peers and the exact kernel.
// --overlay_full lifts the first two (every operation at every size for every runner).
// Measured on this machine (intersection, one run, machine shared with other jobs):
//   mkbool:rational  blob 1e5 2.9 s, 1e6 49 s; star 1e3 0.3 s, 1e4 > 10 min;
//                    checkerboard 1e3 0.4 s, 1e4 12 s; nested squares 1e2 0.2 s
//   other kernels    checkerboard 1e5 about 17 s each, like exact (which runs there)
//   BoostGeometry    star 1e4 > 120 s (BRIEF §6); checkerboard 1e3 0.8 s, growing as n^2
//   CgalEpeck        blob 1e6 22.5 s, star 1e4 5 s
// A runner not named here (for example a new kernel) runs at every size.
struct SizeLimit {
  std::string_view runner;
  WorkloadKind kind;
  std::size_t max_n;
  bool intersection_unlimited = false;  // the limit holds for the other operations only
  std::optional<Operation> only = std::nullopt;  // the limit holds for this operation only
};
constexpr SizeLimit kSizeLimits[] = {
    {"mkbool:rational", WorkloadKind::blob, 10'000},
    {"mkbool:rational", WorkloadKind::star, 1'000},
    {"mkbool:rational", WorkloadKind::checkerboard, 1'000},
    {"mkbool:rational", WorkloadKind::nested_squares, 100},
    {"mkbool:rational", WorkloadKind::nested_wavy_rings, 100},
    // The rational kernel over Boost's number types: rational's limits (cpp_rational costs
    // about four times mpq_class, so these rows stay within seconds).
    {"mkbool:rational-mp", WorkloadKind::blob, 10'000},
    {"mkbool:rational-mp", WorkloadKind::star, 1'000},
    {"mkbool:rational-mp", WorkloadKind::checkerboard, 1'000},
    {"mkbool:rational-mp", WorkloadKind::nested_squares, 100},
    {"mkbool:rational-mp", WorkloadKind::nested_wavy_rings, 100},
    {"mkbool:rational-cpp", WorkloadKind::blob, 10'000},
    {"mkbool:rational-cpp", WorkloadKind::star, 1'000},
    {"mkbool:rational-cpp", WorkloadKind::checkerboard, 1'000},
    {"mkbool:rational-cpp", WorkloadKind::nested_squares, 100},
    {"mkbool:rational-cpp", WorkloadKind::nested_wavy_rings, 100},
    {"mkbool:adaptive", WorkloadKind::checkerboard, 10'000},
    {"mkbool:interval", WorkloadKind::checkerboard, 10'000},
    {"mkbool:cgal", WorkloadKind::checkerboard, 10'000},
    {"mkbool:double", WorkloadKind::checkerboard, 10'000},
    {"BoostGeometry", WorkloadKind::star, 1'000},
    {"BoostGeometry", WorkloadKind::checkerboard, 1'000},
    // Issue 14's shapes: the slow runners stop at sizes of seconds (stripes 8,000 is the
    // issue's row, kept for Boost.Geometry: 3.7 s there).
    {"BoostGeometry", WorkloadKind::stripes, 8'000},
    {"BoostGeometry", WorkloadKind::checkerboard_shared, 1'000},
    {"BoostGeometry", WorkloadKind::checkerboard_offset, 1'000},
    {"BoostGeometry", WorkloadKind::many_holes, 1'000},  // 10^4: 30 s (quadratic)
    {"BoostGeometry", WorkloadKind::long_spikes, 10'000},  // quadratic: minutes at 10^5
    {"CgalEpeck", WorkloadKind::stripes, 8'000},
    {"CgalEpeck", WorkloadKind::checkerboard_shared, 10'000},
    {"CgalEpeck", WorkloadKind::checkerboard_offset, 10'000},
    {"CgalEpeck", WorkloadKind::many_holes, 10'000},
    {"CgalEpeck", WorkloadKind::long_spikes, 100'000},
    // Clipper's PolyTree on the checkerboard's union, difference and symmetric difference
    // (squares touching at corners): 3.1 s at 10^3, more than 10 minutes at 10^4, measured
    // 2026-11-29; its intersection (the bar's row) runs at every size.
    {"ClipperPolyTree", WorkloadKind::checkerboard, 1'000, true},
    {"CgalEpeck", WorkloadKind::star, 10'000},  // 5 s at 10^4
    // Clipper's PolyTree on the symmetric difference of a grid's dark and light cells (the
    // whole grid, one polygon): 7.9 s at 10^3, more than 4 minutes at 10^4 (JoinCommonEdges'
    // FixupFirstLefts2, quadratic), measured 2026-11-29; its other operations run to 10^5.
    {"ClipperPolyTree", WorkloadKind::checkerboard_shared, 1'000, false, Operation::symmetric_difference},
    // Nested squares: every peer grows faster than n^1.4 there (their noders pair the
    // monotone chains of every ring with those of every ring around it). Intersection,
    // 2026-11-29: GEOS 1.6 s at 10^3, more than 100 s at 10^4; Clipper 1.0 s at 10^3, more
    // than 100 s at 10^4; Boost.Geometry 93 ms at 10^3, 11.8 s at 10^4; CGAL 71 ms at 10^3,
    // 1.8 s at 10^4. mkbool's union: 12 ms, 103 ms, 1.15 s at 10^3, 10^4, 10^5.
    {"GEOS", WorkloadKind::nested_squares, 1'000},
    {"BoostGeometry", WorkloadKind::nested_squares, 1'000},
    {"Clipper", WorkloadKind::nested_squares, 1'000},
    {"ClipperPolyTree", WorkloadKind::nested_squares, 1'000},
    {"CgalEpeck", WorkloadKind::nested_squares, 10'000},
    // Nested wavy rings: the peers pair every ring's chains or edges with those of the
    // rings around it. Intersection, 2026-11-29: GEOS 230 ms at 10^2, 25.3 s at 10^3;
    // Boost.Geometry 945 ms, Clipper and its PolyTree 345 ms at 10^2, each more than 100 s
    // at 10^3; CGAL 233 ms and 3.5 s. mkbool's kernels that are not exact over double
    // points keep the box search there (2.3 to 2.7 s at 10^3; `exact` 0.51 s).
    {"GEOS", WorkloadKind::nested_wavy_rings, 100},
    {"BoostGeometry", WorkloadKind::nested_wavy_rings, 100},
    {"Clipper", WorkloadKind::nested_wavy_rings, 100},
    {"ClipperPolyTree", WorkloadKind::nested_wavy_rings, 100},
    {"CgalEpeck", WorkloadKind::nested_wavy_rings, 1'000},
    {"mkbool:double", WorkloadKind::nested_wavy_rings, 1'000},
    {"mkbool:cgal", WorkloadKind::nested_wavy_rings, 1'000},
    {"mkbool:adaptive", WorkloadKind::nested_wavy_rings, 1'000},
    {"mkbool:interval", WorkloadKind::nested_wavy_rings, 1'000},
};

constexpr std::string_view kRepeatedAtLargest[] = {"GEOS", "BoostGeometry", "Clipper", "mkbool:exact"};
constexpr std::string_view kEveryOperationAtLargest[] = {"mkbool:exact", "GEOS", "BoostGeometry", "Clipper",
                                                         "ClipperPolyTree"};

bool named_in(std::string_view runner, std::span<const std::string_view> names) {
  return std::find(names.begin(), names.end(), runner) != names.end();
}

bool full_run = false;  // --overlay_full
bool default_malloc = false;  // --overlay_default_malloc

// Issue 14's workloads (stripes, the two other checkerboards, many holes, long spikes):
// mkbool kernels other than `exact` run up to 10^4 there, the rational ones up to 10^3.
bool is_issue14_workload(WorkloadKind kind) {
  return kind == WorkloadKind::stripes || kind == WorkloadKind::checkerboard_shared ||
         kind == WorkloadKind::checkerboard_offset || kind == WorkloadKind::many_holes ||
         kind == WorkloadKind::long_spikes;
}

bool within_limits(std::string_view runner, WorkloadKind kind, std::size_t n, Operation op) {
  if (full_run) return true;
  if (n == kHugeSize) return op == Operation::intersection && named_in(runner, kAtHugeSize);
  if (is_issue14_workload(kind) && runner.starts_with("mkbool:") && runner != "mkbool:exact") {
    return n <= (runner.starts_with("mkbool:rational") ? 1'000u : 10'000u);
  }
  for (const SizeLimit& l : kSizeLimits) {
    if (l.runner == runner && l.kind == kind && n > l.max_n && !(l.intersection_unlimited && op == Operation::intersection) &&
        (!l.only || *l.only == op)) {
      return false;
    }
  }
  return true;
}

// The largest of a workload's regular sizes (kHugeSize is not one).
std::size_t largest_size(WorkloadKind kind) {
  std::size_t largest = 0;
  for (const auto& [k, sizes] : kSizes) {
    if (k != kind) continue;
    for (const std::size_t n : sizes) {
      if (n != kHugeSize) largest = std::max(largest, n);
    }
  }
  return largest;
}

bool runs_operation(std::string_view runner, WorkloadKind kind, std::size_t n, Operation op) {
  if (full_run || op == Operation::intersection || n < largest_size(kind)) return true;
  return n == largest_size(kind) && named_in(runner, kEveryOperationAtLargest);
}

bool measured_once(std::string_view runner, WorkloadKind kind, std::size_t n) {
  if (n < largest_size(kind)) return false;
  if (kind != WorkloadKind::blob || n == kHugeSize) return true;
  return !named_in(runner, kRepeatedAtLargest);
}

// Joins strings. ("literal" + std::string) trips GCC 12's -Wrestrict false positive.
std::string join(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (const std::string_view p : parts) s.append(p);
  return s;
}

std::string runner_name(std::string_view kernel) { return join({"mkbool:", kernel}); }

struct Case {
  WorkloadKind kind;
  std::size_t n;
  Operation op;
};

// The workload of the benchmark being run. Benchmarks are registered (and so run, with
// their repetitions) grouped by workload and size, so one slot avoids regenerating inputs
// without holding every size in memory at once.
const Workload& workload(WorkloadKind kind, std::size_t n) {
  static std::optional<Workload> current;
  if (!current || current->kind != kind || current->n != n) {
    current.reset();
    current = make_workload(kind, n);
  }
  return *current;
}

// The exact kernel that gives the reference area: the first exact name in kernel_names()
// (they are listed fastest exact first, so "exact" once it is built, else "rational").
std::string reference_kernel() {
  for (const std::string_view k : kernel_names()) {
    if (is_exact_kernel(k)) return std::string(k);
  }
  return {};
}

using CaseKey = std::tuple<WorkloadKind, std::size_t, Operation>;

// Reference areas known so far. The reference kernel's own benchmark fills its entries
// (it is registered before the peers), so the reference costs no extra run unless that
// benchmark is filtered out.
std::map<CaseKey, std::optional<double>>& reference_cache() {
  static std::map<CaseKey, std::optional<double>> cache;
  return cache;
}

std::optional<double> compute_reference(const Case& c, const std::string& kernel);

// mkbool's exact area of a case, rounded to the nearest double, computed once. None when no
// exact kernel may run at this size (see kSizeLimits) or the result is unbounded.
std::optional<double> reference_area(const Case& c) {
  auto& cache = reference_cache();
  const CaseKey key{c.kind, c.n, c.op};
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  std::optional<double> area;
  const std::string kernel = reference_kernel();
  if (!kernel.empty() && within_limits(runner_name(kernel), c.kind, c.n, c.op)) area = compute_reference(c, kernel);
  if (area && std::isnan(*area)) area.reset();
  return cache[key] = area;
}

void set_common_counters(benchmark::State& state, const Case& c, std::size_t vertices_out, double area) {
  state.counters["vertices_in"] = static_cast<double>(workload(c.kind, c.n).vertices());
  state.counters["vertices_out"] = static_cast<double>(vertices_out);
  if (const auto ref = reference_area(c)) {
    state.counters["area_rel_diff"] = *ref != 0 ? (area - *ref) / std::abs(*ref) : area - *ref;
    state.SetLabel(join({"ref=", reference_kernel()}));
  } else {
    state.SetLabel("no exact reference at this size");
  }
}

template <class Library>
void bm_peer(benchmark::State& state, const Case& c) {
  const Workload& w = workload(c.kind, c.n);
  try {
    const PeerOverlay<Library> peer(w.a_ogc, w.b_ogc);
    OverlayResult r;
    for (auto _ : state) {
      r = peer.run(c.op);
      benchmark::DoNotOptimize(r);
    }
    set_common_counters(state, c, r.vertices, r.area);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

// An mkbool kernel known here at compile time: boolean_op<K> directly, inputs converted to
// the kernel's points outside the timed region; timed with the result as the library and
// the command return it (to_output: rounded rings, holes assigned to their shells), as the
// peers return polygons with holes.
template <Kernel K>
void bm_mkbool(benchmark::State& state, const Case& c) {
  const Workload& w = workload(c.kind, c.n);
  const auto a = to_kernel_polygon<K>(w.a);
  const auto b = to_kernel_polygon<K>(w.b);
  const Options options{c.op, true, EfOrganisation::hash, PairSearch::sweep};
  try {
    Stats stats;
    std::optional<double> area;
    for (auto _ : state) {
      const BooleanResult<K> r = boolean_op<K>(a, b, options);
      const Output out = to_output<K, ExactKernel>(r, false);
      benchmark::DoNotOptimize(out.polygons.data());
      stats = r.stats;
      if (!area) {  // the result is the same every iteration: its area is taken once
        state.PauseTiming();
        area = result_area(r);
        state.ResumeTiming();
      }
    }
    if (K::name == reference_kernel() && area && !std::isnan(*area)) {
      reference_cache().try_emplace(CaseKey{c.kind, c.n, c.op}, *area);
    }
    state.counters["crossings"] = static_cast<double>(stats.crossings);
    set_common_counters(state, c, stats.vertices_out, area.value_or(std::numeric_limits<double>::quiet_NaN()));
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

// Any other kernel in kernel_names(), through the runtime API: the time is the API's op_ns
// (the operation alone; input conversion and output assembly are not counted: such a
// kernel's rows miss the assembly that bm_mkbool times).
void bm_mkbool_by_name(benchmark::State& state, const Case& c, const std::string& kernel) {
  const Workload& w = workload(c.kind, c.n);
  try {
    BooleanStats stats;
    for (auto _ : state) {
      stats = compute(w.a, w.b, BooleanOptions{c.op, true, kernel}).stats;
      state.SetIterationTime(static_cast<double>(stats.op_ns) * 1e-9);
    }
    state.counters["crossings"] = static_cast<double>(stats.crossings);
    set_common_counters(state, c, stats.vertices_out, stats.area.value_or(std::numeric_limits<double>::quiet_NaN()));
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

struct Runner {
  std::string name;
  std::function<void(benchmark::State&, const Case&)> run;
  bool manual_time = false;  // the runner reports its own time (mk::compute's op_ns)
};

// The kernels timed through boolean_op<K> directly. A kernel in kernel_names() but not in
// this list is still benchmarked, through mk::compute (bm_mkbool_by_name); adding it here
// (and its header above) only lowers the harness's overhead per iteration.
template <Kernel... Ks>
struct KernelList {};
using TemplateKernels = KernelList<ExactKernel, RationalKernel, AdaptiveKernel, IntervalKernel,
#ifdef MK_WITH_CGAL
                                   CgalKernel,
#endif
                                   DoubleKernel>;

template <Kernel... Ks>
bool add_template_runner(KernelList<Ks...>, std::string_view kernel, const std::string& name, std::vector<Runner>& out) {
  return ((kernel == Ks::name ? (out.push_back({name, bm_mkbool<Ks>}), true) : false) || ...);
}

template <Kernel... Ks>
std::optional<double> reference_by_template(KernelList<Ks...>, const Case& c, const std::string& kernel) {
  std::optional<double> area;
  const auto run = [&]<Kernel K>(K) {
    if constexpr (K::is_exact) {
      const Workload& w = workload(c.kind, c.n);
      area = exact_area_nearest(boolean_op<K>(w.a, w.b, Options{c.op, true, EfOrganisation::hash, PairSearch::sweep}));
    }
  };
  ((kernel == Ks::name ? (run(Ks{}), true) : false) || ...);
  return area;
}

std::optional<double> compute_reference(const Case& c, const std::string& kernel) {
  if (auto area = reference_by_template(TemplateKernels{}, c, kernel)) return area;
  const Workload& w = workload(c.kind, c.n);
  return compute(w.a, w.b, BooleanOptions{c.op, true, kernel}).stats.area;
}

std::vector<Runner> runners() {
  std::vector<Runner> out;
  std::string names;
  for (const std::string_view k : kernel_names()) names.append(names.empty() ? "" : ",").append(k);
  benchmark::AddCustomContext("mkbool_kernels", names);
  benchmark::AddCustomContext("mkbool_reference_kernel", reference_kernel());
  benchmark::AddCustomContext("overlay_full", full_run ? "true" : "false");
  for (const std::string_view k : kernel_names()) {
    const std::string name = runner_name(k);
    if (!add_template_runner(TemplateKernels{}, k, name, out)) {
      const auto by_name = [kernel = std::string(k)](benchmark::State& s, const Case& c) {
        bm_mkbool_by_name(s, c, kernel);
      };
      out.push_back({name, by_name, true});
    }
  }
  // The peers come after the kernels: the reference kernel's benchmark then fills the
  // reference areas they are compared with.
  const auto add_peer = [&]<class Library>(Library) {
    out.push_back({std::string(Library::name), bm_peer<Library>});
    benchmark::AddCustomContext(std::string(Library::name) + "_version", PeerOverlay<Library>::version());
  };
#ifdef MK_HAVE_GEOS
  add_peer(Geos{});
#endif
#ifdef MK_HAVE_BOOST_GEOMETRY
  add_peer(BoostGeometry{});
#endif
#ifdef MK_HAVE_CLIPPER
  add_peer(Clipper{});
  add_peer(ClipperPolyTree{});
#endif
#ifdef MK_HAVE_CGAL
  add_peer(CgalEpeck{});
#endif
  (void)add_peer;
  return out;
}

void register_benchmarks() {
  const auto all = runners();
  for (const auto& [kind, sizes] : kSizes) {
    for (const std::size_t n : sizes) {
      for (const Operation op : kOperations) {
        for (const Runner& r : all) {
          if (!within_limits(r.name, kind, n, op) || !runs_operation(r.name, kind, n, op)) continue;
          const Case c{kind, n, op};
          const std::string name = join({"BM_Overlay<", r.name, ">/", workload_name(kind), "/", operation_name(op),
                                         "/", std::to_string(n)});
          auto* b = benchmark::RegisterBenchmark(name.c_str(), [run = r.run, c](benchmark::State& s) { run(s, c); });
          b->Unit(benchmark::kMillisecond);
          if (r.manual_time) {
            b->UseManualTime();
          } else {
            b->UseRealTime();  // CGAL runs in a thread of its own: CPU time would miss it
          }
          if (measured_once(r.name, kind, n)) {
            b->Iterations(1)->Repetitions(1);
          } else {
            // Every runner gets the same warm-up before its first measured repetition (caches,
            // lazily built tables, the allocator's free lists).
            b->MinWarmUpTime(0.05);
            b->MinTime(0.1);
          }
        }
      }
    }
  }
}

}  // namespace

}  // namespace mk::bench

int main(int argc, char** argv) {
  // Our own flag first: Google Benchmark reports flags it does not know.
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--overlay_full") == 0) {
      mk::bench::full_run = true;
    } else if (std::strcmp(argv[i], "--overlay_default_malloc") == 0) {
      mk::bench::default_malloc = true;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  // The same allocator setting for every library in this process: glibc keeps freed memory
  // instead of returning it to the kernel (no mmap for large blocks, no trimming), so that
  // repeated runs measure computation rather than first-touch page faults, which cost about
  // 8 us each on the VM these figures come from (bench/README.md, "What is timed").
  // --overlay_default_malloc measures with glibc's defaults instead.
  if (!mk::bench::default_malloc) {
    if (mallopt(M_MMAP_MAX, 0) != 1 || mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max()) != 1) {
      std::fprintf(stderr, "bench_overlay: mallopt failed\n");
      return 1;
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("malloc", mk::bench::default_malloc ? "glibc default" : "no mmap, no trim");
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;  // a usage error, as everywhere
  mk::bench::register_benchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
