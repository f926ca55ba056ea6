// What the exact result costs after the operation: BM_OutputCost/<workload>/<n> runs the
// exact kernel's operation and then each step that turns its result into what a user
// reads, timing them apart: rounding, the exact validity check and the assembly into
// polygons with holes (mk::to_output), writing WKT, the correctly rounded area, and the
// exact area as a reduced rational with its decimal text.
// [BRIEF §6a] (output: exact inside, doubles or rationals outside) [issue 17's bars]
// Preconditions: built in Release.
//
// Counters (seconds per iteration, and ratios to the operation):
//   op_s          the operation (boolean_op, the exact kernel)
//   output_s      rounding, validity check, assembly (to_output without exact strings)
//   wkt_s         write_wkt of the assembled result
//   wkt_cpu_s     the processor time of all threads in write_wkt: its work whatever the load
//                 (on a shared machine wkt_s waits for a second core that is not free)
//   certify_s     certified rounding after to_output (issue 12): nothing more than a check
//                 of the report when the nearest doubles are valid, snap rounding otherwise
//   certify_ratio certify_s / op_s
//   rounding_s    rounding every vertex to its nearest double (part of output_s, again)
//   validity_s    the exact validity check of the rounded result (part of output_s, again)
//   rounding_ratio (rounding_s + validity_s + certify_s) / op_s
//   rules_s       what step 3 spends on the rounding certificate's rules N and C
//                 (separation_rules.hpp): step 3 timed with them and without
//                 (Options::rounding_rules), five times each per iteration, the difference
//                 of the medians (about 0 where the rules do not run; noise can make it < 0)
//   rounding_all_ratio (rounding_s + validity_s + certify_s + rules_s) / (op_s - rules_s):
//                 all that certified rounding costs, over the operation without it; issue
//                 12's bar is 0.10 (rules_s taken as 0 when negative)
//   area_s        the area rounded to the nearest double (filtered sum)
//   area_exact_s  the exact area and its decimal text ("p/q")
//   write_ratio   (output_s + wkt_s) / op_s: the bar is 0.25
//   stats_ratio   area_exact_s / op_s: the bar is 2
//   to_chars_cpu_s processor time of std::to_chars on every written coordinate, one thread
//   text_floor_ratio to_chars_cpu_s / threads / op_s: the part of write_ratio that the
//                 shortest text of the doubles alone takes, even if perfectly parallel
//   area_gcd_s    GMP's gcd of the reduced area's numerator and denominator (what checking
//                 or making it reduced costs at least)
//   area_text_s   GMP's decimal text of the reduced area alone
//   gmp_floor_ratio (area_gcd_s + area_text_s) / op_s: what any exact area as reduced
//                 decimal text costs with GMP, against the bar of 2
// The benchmark's own time is op_s + output_s + wkt_s: what the command's user waits for
// after reading the input, without --stats.
#include <benchmark/benchmark.h>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <limits>
#include <malloc.h>
#include <optional>
#include <string>

#include "api/area.hpp"
#include "api/certified_rounding.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "bench/workloads.hpp"
#include "core/boolean_op.hpp"
#include "core/to_output.hpp"
#include "io/wkt.hpp"

namespace mk::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void BM_OutputCost(benchmark::State& state, WorkloadKind kind) {
  const Workload w = make_workload(kind, static_cast<std::size_t>(state.range(0)));
  Options opt;
  opt.op = Operation::intersection;
  double op = 0, output = 0, certify = 0, wkt = 0, wkt_cpu = 0, area = 0, area_exact = 0, rounding = 0, validity = 0;
  double area_gcd = 0, area_text = 0, to_chars_cpu = 0, rules = 0;
  bool snapped = false;
  // Step 3 alone, from the trace hook's calls after steps 2 and 3.
  Clock::time_point step3_start;
  double step3 = 0;
  const TraceHook<ExactKernel> time_step3 = [&](Step s, const Arrangement<ExactKernel>&) {
    if (s == Step::vertex_rings) step3_start = Clock::now();
    if (s == Step::intersections) step3 = seconds_since(step3_start);
  };
  const auto median_of_5 = [](std::array<double, 5> v) {
    std::sort(v.begin(), v.end());
    return v[2];
  };
  std::size_t digits = 0;
  for (auto _ : state) {
    const double waited_before = op + output + wkt;
    auto t = Clock::now();
    const BooleanResult<ExactKernel> r = boolean_op<ExactKernel>(w.a, w.b, opt, time_step3);
    op += seconds_since(t);
    // Step 3 with the rules (this run's and four more) and without (five), alternately.
    {
      std::array<double, 5> with{step3}, without{};
      Options plain = opt;
      plain.rounding_rules = false;
      for (std::size_t k = 0; k < 5; ++k) {
        benchmark::DoNotOptimize(boolean_op<ExactKernel>(w.a, w.b, plain, time_step3).cycles.size());
        without[k] = step3;
        if (k == 4) break;
        benchmark::DoNotOptimize(boolean_op<ExactKernel>(w.a, w.b, opt, time_step3).cycles.size());
        with[k + 1] = step3;
      }
      rules += median_of_5(with) - median_of_5(without);
    }
    t = Clock::now();
    Output out = to_output<ExactKernel, ExactKernel>(r, false, resolve_threads(opt.threads));
    output += seconds_since(t);
    t = Clock::now();
    certify_rounding(r, out, RoundingMode::certified, std::nullopt);
    certify += seconds_since(t);
    // The two parts of to_output that certified rounding consists of when the nearest
    // doubles are valid, timed again apart and done as to_output does them: rounding every
    // vertex (with the half-sizes of its box when the certificate of boxes may be asked),
    // and the validity check of the rounded result (certificates, else the full OGC sweep).
    const bool many_crossings = rounding_wants_halves(r);
    RoundingHalves halves;
    t = Clock::now();
    const std::vector<std::vector<Point>> nearest =
        detail::rounded_cycles(r, resolve_threads(opt.threads), many_crossings ? &halves : nullptr);
    rounding += seconds_since(t);
    const std::vector<std::vector<int>> polygon_cycles = result_polygon_cycles(r);
    t = Clock::now();
    const bool valid = is_valid_rounded_result_ogc<ExactKernel, ExactKernel>(
        r, nearest, polygon_cycles, resolve_threads(opt.threads), many_crossings ? &halves : nullptr);
    validity += seconds_since(t);
    benchmark::DoNotOptimize(valid);
    snapped = snapped || out.rounding.snapped;
    t = Clock::now();
    const std::clock_t cpu = std::clock();
    const std::string text = write_wkt(out, opt.threads);
    wkt += seconds_since(t);
    wkt_cpu += static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
    benchmark::DoNotOptimize(text.data());
    // The shortest round-trip text of every written coordinate and nothing else, on one
    // thread (std::to_chars, the fastest such formatter in Debian's packages here): a floor
    // under any WKT writer that writes every double so that it reads back exactly.
    {
      const std::clock_t c0 = std::clock();
      char buf[32];
      std::size_t chars = 0;
      const auto put = [&](const Point& p) {
        chars += static_cast<std::size_t>(std::to_chars(buf, buf + sizeof buf, p.x).ptr - buf);
        chars += static_cast<std::size_t>(std::to_chars(buf, buf + sizeof buf, p.y).ptr - buf);
      };
      for (const auto& pg : out.polygons) {
        for (const Point& p : pg.shell) put(p);
        for (const auto& h : pg.holes) {
          for (const Point& p : h) put(p);
        }
      }
      benchmark::DoNotOptimize(chars);
      to_chars_cpu += static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    }
    t = Clock::now();
    const auto rounded = rounded_area(r);
    area += seconds_since(t);
    benchmark::DoNotOptimize(rounded);
    t = Clock::now();
    const std::optional<mpq_class> q = exact_area(r);
    const std::string exact = q->get_str();
    area_exact += seconds_since(t);
    digits = exact.size();
    // What GMP alone spends on an answer of this size, whatever sums it: one gcd of its two
    // parts (a reduction needs at least that one, on parts at least this large) and the
    // decimal text.
    t = Clock::now();
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), q->get_num_mpz_t(), q->get_den_mpz_t());
    benchmark::DoNotOptimize(g.get_mpz_t());
    area_gcd += seconds_since(t);
    t = Clock::now();
    benchmark::DoNotOptimize(q->get_str().size());
    area_text += seconds_since(t);
    state.SetIterationTime(op + output + wkt - waited_before);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["op_s"] = op / n;
  state.counters["output_s"] = output / n;
  state.counters["wkt_s"] = wkt / n;
  state.counters["wkt_cpu_s"] = wkt_cpu / n;
  state.counters["certify_s"] = certify / n;
  state.counters["certify_ratio"] = certify / op;
  state.counters["rounding_s"] = rounding / n;
  state.counters["validity_s"] = validity / n;
  // Issue 12's bar (at most 0.10 when the nearest doubles are valid): rounding to nearest,
  // the validity check that certifies it, and certify_rounding's own step, over the operation.
  state.counters["rounding_ratio"] = (rounding + validity + certify) / op;
  state.counters["rules_s"] = rules / n;
  const double rules_cost = std::max(rules, 0.0);
  state.counters["rounding_all_ratio"] = (rounding + validity + certify + rules_cost) / (op - rules_cost);
  state.counters["snapped"] = snapped ? 1 : 0;
  state.counters["area_s"] = area / n;
  state.counters["area_exact_s"] = area_exact / n;
  state.counters["write_ratio"] = (output + wkt) / op;
  state.counters["stats_ratio"] = area_exact / op;
  state.counters["to_chars_cpu_s"] = to_chars_cpu / n;
  // (to_chars_cpu_s over the writer's threads, ideally shared) / op_s: writing's floor.
  state.counters["text_floor_ratio"] = to_chars_cpu / static_cast<double>(resolve_threads(opt.threads)) / op;
  state.counters["area_gcd_s"] = area_gcd / n;
  state.counters["area_text_s"] = area_text / n;
  state.counters["gmp_floor_ratio"] = (area_gcd + area_text) / op;
  state.counters["area_exact_chars"] = static_cast<double>(digits);
  state.counters["vertices_in"] = static_cast<double>(w.vertices());
}

void register_all() {
  struct Case {
    WorkloadKind kind;
    long n;
    int iterations;
  };
  // Large cases run once per repetition: the exact area of star 1e4 alone takes seconds.
  for (const Case c : {Case{WorkloadKind::blob, 100'000, 5}, Case{WorkloadKind::blob, 1'000'000, 1},
                       Case{WorkloadKind::star, 1'000, 5}, Case{WorkloadKind::star, 10'000, 1}}) {
    const std::string name = "BM_OutputCost/" + std::string(workload_name(c.kind));
    benchmark::RegisterBenchmark(name.c_str(), [k = c.kind](benchmark::State& s) { BM_OutputCost(s, k); })
        ->Arg(c.n)
        ->Iterations(c.iterations)
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime();
  }
}

}  // namespace
}  // namespace mk::bench

int main(int argc, char** argv) {
  // The allocator as the command sets it (cli/main.cpp) and bench_overlay measures with it:
  // freed memory kept, not returned to the kernel. With glibc's defaults every phase faults
  // its large arrays in again, which made the operation up to 5x slower here (blob 10^6:
  // 465 against 91 ms) and so every ratio to it too small.
  if (mallopt(M_MMAP_MAX, 0) != 1 || mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max()) != 1) {
    std::fprintf(stderr, "bench_output: mallopt failed\n");
    return 1;
  }
  mk::bench::register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("malloc", "no mmap, no trim");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
