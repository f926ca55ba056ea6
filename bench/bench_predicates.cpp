// Speed of the orientation predicates per call: naive double, adaptive (expansions),
// interval filter with its escalating stages, each of those stages alone, the GMP
// evaluations and the rational kernels over three number types, on random, near-degenerate
// and exactly degenerate input. [Sh97 §5] (timings of adaptive predicates) [MK89 §3.3]
// Preconditions: a Release build. Each benchmark iteration is one predicate call, cycling
// through 4096 precomputed inputs, so the Time column reads as ns per call. Built with
// MK_COUNTERS=ON, the adaptive and interval rows also report the share of calls each stage
// decided (timings then include the counting).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/exact_reference.hpp"
#include "arithmetic/interval_filter.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/kernels/rational_mp_kernels.hpp"
#include "arithmetic/mpfr_interval.hpp"
#include "arithmetic/predicates_counters.hpp"
#include "arithmetic/predicates_gmp.hpp"
#include "arithmetic/predicates_naive.hpp"
#ifdef MK_WITH_CGAL
#include "arithmetic/kernels/cgal_kernel.hpp"
#endif

namespace {

// ---- The kinds, one per back end ----------------------------------------------------
struct Double {
  static constexpr const char* name = "Double";
  static int orient2d(const double* v) { return mk::naive::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]); }
  static int orient_vectors(const double* v) {
    return mk::naive::orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  }
};
struct Adaptive {
  static constexpr const char* name = "Adaptive";
  static constexpr auto method = mk::PredicateMethod::adaptive;
  static int orient2d(const double* v) { return mk::adaptive::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]); }
  static int orient_vectors(const double* v) {
    return mk::adaptive::orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  }
};
struct Interval {
  static constexpr const char* name = "Interval";
  static constexpr auto method = mk::PredicateMethod::interval;
  static int orient2d(const double* v) {
    return mk::interval_filter::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]);
  }
  static int orient_vectors(const double* v) {
    return mk::interval_filter::orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  }
};
#ifdef MK_WITH_CGAL
// CgalKernel's predicates: CGAL::orientation on Epick points (CGAL's static and dynamic
// filters, then its exact number type), and CgalKernel::orient_vectors.
struct Cgal {
  static constexpr const char* name = "Cgal";
  static int orient2d(const double* v) {
    return static_cast<int>(mk::CgalKernel::orient2d({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}));
  }
  static int orient_vectors(const double* v) {
    return static_cast<int>(mk::CgalKernel::orient_vectors({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}));
  }
};
#endif

// The interval predicate's stages alone, each on every input (an undecided call, 2, costs
// what it costs): Boost.Interval on doubles, then MPFR intervals at 128 and 256 bits.
struct IntervalStage {
  static constexpr const char* name = "IntervalStage";
  static int orient2d(const double* v) {
    return mk::interval_filter::detail::interval_sign(v[0], v[1], v[2], v[3], v[0], v[1], v[4], v[5]);
  }
  static int orient_vectors(const double* v) {
    return mk::interval_filter::detail::interval_sign(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  }
};
template <mpfr_prec_t Bits>
struct MpfrStage {
  static constexpr const char* name = Bits == 128 ? "Mpfr128Stage" : "Mpfr256Stage";
  static int orient2d(const double* v) {
    return mk::mpfr_interval::cross_sign<Bits>(v[0], v[1], v[2], v[3], v[0], v[1], v[4], v[5]);
  }
  static int orient_vectors(const double* v) {
    return mk::mpfr_interval::cross_sign<Bits>(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  }
};

// The ground truth of the tests: mpq rationals.
struct Rational {
  static constexpr const char* name = "Rational";
  static int orient2d(const double* v) { return mk::reference::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]); }
  static int orient_vectors(const double* v) {
    return mk::reference::orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  }
};
// The last stage of adaptive and interval: integers after a common power-of-two scaling.
struct GmpFallback {
  static constexpr const char* name = "GmpFallback";
  static int orient2d(const double* v) { return mk::gmp::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]); }
  static int orient_vectors(const double* v) {
    return mk::gmp::orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  }
};

// ---- Inputs: 4096 sets of 8 coordinates (orient2d reads the first 6) -------------------
constexpr std::size_t input_count = 4096;
using Inputs = std::vector<std::array<double, 8>>;

// Uniform in [-1, 1]: the filter decides every call.
Inputs random_inputs() {
  std::mt19937_64 rng(5001);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Inputs in(input_count);
  for (auto& v : in)
    for (double& x : v) x = d(rng);
  return in;
}

// collinear_exact: points base + t (p, q) on integer lines, times 2^-10. Differences are
// exact, so adaptive decides at stage B. orient_vectors gets two segments of the line.
Inputs collinear_inputs() {
  std::mt19937_64 rng(5002);
  std::uniform_int_distribution<long> base(-(1L << 20), 1L << 20), dir(-1000, 1000), step(-1000, 1000);
  Inputs in(input_count);
  for (auto& v : in) {
    const long x0 = base(rng), y0 = base(rng), p = dir(rng), q = dir(rng) | 1;
    for (std::size_t i = 0; i < 8; i += 2) {
      const long t = step(rng);
      v[i] = std::ldexp(static_cast<double>(x0 + t * p), -10);
      v[i + 1] = std::ldexp(static_cast<double>(y0 + t * q), -10);
    }
  }
  return in;
}

// collinear_exact with rounded differences: (3x, kx) on y = (k/3) x, x with 45 significant
// bits spread over 2^-20..2^20, so adaptive needs stages C and exact.
Inputs collinear_inexact_inputs() {
  std::mt19937_64 rng(5003);
  std::uniform_int_distribution<int> exponent(-20, 20), slope(1, 60);
  Inputs in(input_count);
  for (auto& v : in) {
    const double k = 2 * slope(rng) - 1;
    for (std::size_t i = 0; i < 8; i += 2) {
      const double x = std::ldexp(static_cast<double>((rng() >> 19) | (std::uint64_t{1} << 44)), exponent(rng) - 44);
      v[i] = 3 * x;
      v[i + 1] = k * x;
    }
  }
  return in;
}

// near_collinear: the last point (orient2d) or the second segment (orient_vectors) on the
// line through two random points of [-1, 1]^2, computed in double and moved 1 or 2 ulps:
// D is tiny and rarely zero, beyond the semi-static filter; the interval stages decide it.
Inputs near_collinear_inputs() {
  std::mt19937_64 rng(5004);
  std::uniform_real_distribution<double> d(-1.0, 1.0), t(-2.0, 2.0);
  std::uniform_int_distribution<int> ulps(-2, 2);
  Inputs in(input_count);
  for (auto& v : in) {
    const double ax = d(rng), ay = d(rng), bx = d(rng), by = d(rng);
    v[0] = ax, v[1] = ay, v[2] = bx, v[3] = by;
    for (std::size_t i = 4; i < 8; i += 2) {
      const double s = t(rng);
      v[i] = ax + s * (bx - ax);
      double y = ay + s * (by - ay);
      for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) y = std::nextafter(y, k > 0 ? HUGE_VAL : -HUGE_VAL);
      v[i + 1] = y;
    }
  }
  return in;
}

const Inputs& inputs(int which) {
  static const std::array<Inputs, 4> all{random_inputs(), near_collinear_inputs(), collinear_inputs(),
                                         collinear_inexact_inputs()};
  return all[static_cast<std::size_t>(which)];
}
constexpr std::array<const char*, 4> input_names{"random", "near_collinear", "collinear", "collinear_inexact"};

// Built with MK_COUNTERS=ON: the share of calls each stage of the kind's method decided,
// one counter per stage that decided any (timings then include the counting).
template <class Kind>
void report_stages([[maybe_unused]] benchmark::State& state, [[maybe_unused]] mk::PredicateKind k) {
  if constexpr (mk::PredicateCounters::enabled && requires { Kind::method; }) {
    const auto c = mk::PredicateCounters::read();
    const auto calls = static_cast<double>(c.calls(Kind::method, k));
    if (calls == 0) return;
    const auto share = [&](const auto& stages) {
      for (const auto s : stages) {
        if (const auto n = c.decided(Kind::method, k, s); n > 0) {
          state.counters[std::string(mk::stage_name(s))] = static_cast<double>(n) / calls;
        }
      }
    };
    if (Kind::method == mk::PredicateMethod::adaptive) {
      share(mk::adaptive_stages);
    } else {
      share(mk::interval_stages);
    }
  }
}

template <class Kind>
void BM_Orient2d(benchmark::State& state, int which) {
  const Inputs& in = inputs(which);
  mk::PredicateCounters::reset();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(Kind::orient2d(in[i].data()));
    i = (i + 1) % input_count;
  }
  report_stages<Kind>(state, mk::PredicateKind::orient2d);
}

template <class Kind>
void BM_OrientVectors(benchmark::State& state, int which) {
  const Inputs& in = inputs(which);
  mk::PredicateCounters::reset();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(Kind::orient_vectors(in[i].data()));
    i = (i + 1) % input_count;
  }
  report_stages<Kind>(state, mk::PredicateKind::orient_vectors);
}

// The rational kernel's predicates over each number type, on points converted once (as the
// kernel holds them): the cost of exact evaluation by number type alone.
template <class K>
struct RationalKernelKind {
  using Points = std::vector<std::array<typename K::Point, 4>>;
  static const Points& points(int which) {
    static std::array<Points, input_names.size()> cache;
    Points& p = cache[static_cast<std::size_t>(which)];
    if (p.empty()) {
      for (const auto& v : inputs(which)) {
        p.push_back({K::point({v[0], v[1]}), K::point({v[2], v[3]}), K::point({v[4], v[5]}), K::point({v[6], v[7]})});
      }
    }
    return p;
  }
};

template <class K>
void BM_Orient2dRational(benchmark::State& state, int which) {
  const auto& p = RationalKernelKind<K>::points(which);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(K::orient2d(p[i][0], p[i][1], p[i][2]));
    i = (i + 1) % input_count;
  }
}

template <class K>
void BM_OrientVectorsRational(benchmark::State& state, int which) {
  const auto& p = RationalKernelKind<K>::points(which);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(K::orient_vectors(p[i][0], p[i][1], p[i][2], p[i][3]));
    i = (i + 1) % input_count;
  }
}

template <class K>
void register_rational_kernel(const char* name) {
  for (int which = 0; which < static_cast<int>(input_names.size()); ++which) {
    const std::string suffix = std::string("<") + name + ">/" + input_names[static_cast<std::size_t>(which)];
    benchmark::RegisterBenchmark(("BM_Orient2d" + suffix).c_str(), BM_Orient2dRational<K>, which);
    benchmark::RegisterBenchmark(("BM_OrientVectors" + suffix).c_str(), BM_OrientVectorsRational<K>, which);
  }
}

template <class Kind>
void register_kind() {
  for (int which = 0; which < static_cast<int>(input_names.size()); ++which) {
    const std::string suffix = std::string("<") + Kind::name + ">/" + input_names[static_cast<std::size_t>(which)];
    benchmark::RegisterBenchmark(("BM_Orient2d" + suffix).c_str(), BM_Orient2d<Kind>, which);
    benchmark::RegisterBenchmark(("BM_OrientVectors" + suffix).c_str(), BM_OrientVectors<Kind>, which);
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_kind<Double>();
  register_kind<Adaptive>();
  register_kind<Interval>();
#ifdef MK_WITH_CGAL
  register_kind<Cgal>();
#endif
  register_kind<IntervalStage>();
  register_kind<MpfrStage<128>>();
  register_kind<MpfrStage<256>>();
  register_kind<GmpFallback>();
  register_kind<Rational>();
  register_rational_kernel<mk::RationalKernel>("RationalMpq");
  register_rational_kernel<mk::RationalMpKernel>("RationalMp");
  register_rational_kernel<mk::RationalCppKernel>("RationalCpp");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;  // a usage error, as everywhere
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
