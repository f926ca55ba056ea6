// Per-thread counts of predicate calls and of the stage that decided each one, so that
// experiments and benchmarks can report how often each stage of a staged predicate is
// needed. [Sh97 §4.2] (staged predicates) [MK89 §3.3] (filter, multiprecision fallback)
// Preconditions: none. Counting is compiled in only when MK_PREDICATE_COUNTERS is defined
// (CMake option MK_COUNTERS on mkbool_arith); otherwise call() and decide() are empty and
// read() returns zeros, so callers need no #if of their own.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace mk {

// Which implementation was called.
enum class PredicateMethod : std::uint8_t { adaptive, interval };
// Which predicate was called.
enum class PredicateKind : std::uint8_t { orient2d, orient_vectors };
// The stages that can decide a call, cheapest first. Every call enters `filter` (stage A
// for adaptive, the semi-static bound for interval). interval goes on through `interval`
// (Boost.Interval on doubles), `mpfr_128` and `mpfr_256` (intervals over MPFR numbers) to
// `gmp`; adaptive through `expansion_b` (exact products of exact differences included),
// `fixed_point`, `expansion_c` and `expansion_exact` to `gmp`.
enum class PredicateStage : std::uint8_t {
  filter,
  interval,
  mpfr_128,
  mpfr_256,
  expansion_b,
  fixed_point,
  expansion_c,
  expansion_exact,
  gmp,
};

inline constexpr std::array<PredicateStage, 5> interval_stages{PredicateStage::filter, PredicateStage::interval,
                                                               PredicateStage::mpfr_128, PredicateStage::mpfr_256,
                                                               PredicateStage::gmp};
inline constexpr std::array<PredicateStage, 6> adaptive_stages{
    PredicateStage::filter,      PredicateStage::expansion_b,     PredicateStage::fixed_point,
    PredicateStage::expansion_c, PredicateStage::expansion_exact, PredicateStage::gmp};

constexpr std::string_view stage_name(PredicateStage s) {
  constexpr std::array<std::string_view, 9> names{"filter",      "interval",    "mpfr_128",
                                                  "mpfr_256",    "expansion_b", "fixed_point",
                                                  "expansion_c", "expansion_exact", "gmp"};
  return names[static_cast<std::size_t>(s)];
}
constexpr std::string_view method_name(PredicateMethod m) { return m == PredicateMethod::adaptive ? "adaptive" : "interval"; }
constexpr std::string_view kind_name(PredicateKind k) { return k == PredicateKind::orient2d ? "orient2d" : "orient_vectors"; }

struct PredicateCounters {
  static constexpr bool enabled =
#ifdef MK_PREDICATE_COUNTERS
      true;
#else
      false;
#endif
  static constexpr std::size_t method_count = 2;
  static constexpr std::size_t kind_count = 2;
  static constexpr std::size_t stage_count = 9;

  // entered[pair(m, k)]: calls of method m on predicate k. decided_after_filter[index(m, k,
  // s)]: of those, calls that stage s (past the filter) decided. The filter's own count is
  // the rest, so that the filter's fast path counts once, at entry.
  std::array<std::uint64_t, method_count * kind_count> entered{};
  std::array<std::uint64_t, method_count * kind_count * stage_count> decided_after_filter{};

  static constexpr std::size_t pair(PredicateMethod m, PredicateKind k) {
    return static_cast<std::size_t>(m) * kind_count + static_cast<std::size_t>(k);
  }
  static constexpr std::size_t index(PredicateMethod m, PredicateKind k, PredicateStage s) {
    return pair(m, k) * stage_count + static_cast<std::size_t>(s);
  }
  std::uint64_t calls(PredicateMethod m, PredicateKind k) const { return entered[pair(m, k)]; }
  // Calls that left the filter undecided.
  std::uint64_t past_filter(PredicateMethod m, PredicateKind k) const {
    std::uint64_t n = 0;
    for (std::size_t s = 1; s < stage_count; ++s) n += decided_after_filter[pair(m, k) * stage_count + s];
    return n;
  }
  // Calls that stage s decided.
  std::uint64_t decided(PredicateMethod m, PredicateKind k, PredicateStage s) const {
    return s == PredicateStage::filter ? calls(m, k) - past_filter(m, k) : decided_after_filter[index(m, k, s)];
  }

  // A copy of the calling thread's counters.
  static PredicateCounters read();
  // Zeroes the calling thread's counters.
  static void reset();
  // Records a call of (m, k), at its entry; no-op unless enabled.
  static void call(PredicateMethod m, PredicateKind k);
  // Records that stage s, past the filter, decided a call of (m, k); no-op unless enabled.
  static void decide(PredicateMethod m, PredicateKind k, PredicateStage s);
};

namespace detail {
// thread_local: predicates run concurrently in experiments; each thread counts its own.
inline thread_local PredicateCounters this_thread_predicate_counters;
}  // namespace detail

inline PredicateCounters PredicateCounters::read() { return detail::this_thread_predicate_counters; }

inline void PredicateCounters::reset() { detail::this_thread_predicate_counters = PredicateCounters{}; }

inline void PredicateCounters::call([[maybe_unused]] PredicateMethod m, [[maybe_unused]] PredicateKind k) {
  if constexpr (enabled) ++detail::this_thread_predicate_counters.entered[pair(m, k)];
}

inline void PredicateCounters::decide([[maybe_unused]] PredicateMethod m, [[maybe_unused]] PredicateKind k,
                                      [[maybe_unused]] PredicateStage s) {
  if constexpr (enabled) ++detail::this_thread_predicate_counters.decided_after_filter[index(m, k, s)];
}

}  // namespace mk
