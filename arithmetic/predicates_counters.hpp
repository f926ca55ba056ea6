// Per-thread counts of predicate calls and of the stages each call reached, so experiments
// can report how often a filter fails. [Sh97 §4.2] (staged predicates)
// Preconditions: none. Counting is compiled in only when MK_PREDICATE_COUNTERS is defined
// (CMake option MK_COUNTERS on mkbool_arith); otherwise count() is empty and read()
// returns zeros, so callers need no #if of their own.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace mk {

// Which implementation was called.
enum class PredicateMethod : std::uint8_t { adaptive, interval };
// Which predicate was called.
enum class PredicateKind : std::uint8_t { orient2d, orient_vectors };
// The stages, cheapest first. Every call enters `filter` (stage A for adaptive, the
// semi-static filter for interval); adaptive goes on to the expansion stages, interval to
// `interval`; both end in `gmp` when their own arithmetic cannot decide.
enum class PredicateStage : std::uint8_t {
  filter,
  interval,
  expansion_b,
  expansion_c,
  expansion_exact,
  gmp,
};

struct PredicateCounters {
  static constexpr bool enabled =
#ifdef MK_PREDICATE_COUNTERS
      true;
#else
      false;
#endif
  static constexpr std::size_t method_count = 2;
  static constexpr std::size_t kind_count = 2;
  static constexpr std::size_t stage_count = 6;

  // reached[index(m, k, s)]: calls of method m on predicate k that entered stage s.
  std::array<std::uint64_t, method_count * kind_count * stage_count> reached{};

  static constexpr std::size_t index(PredicateMethod m, PredicateKind k, PredicateStage s) {
    return (static_cast<std::size_t>(m) * kind_count + static_cast<std::size_t>(k)) * stage_count +
           static_cast<std::size_t>(s);
  }
  std::uint64_t calls(PredicateMethod m, PredicateKind k) const {
    return reached[index(m, k, PredicateStage::filter)];
  }
  std::uint64_t reached_stage(PredicateMethod m, PredicateKind k, PredicateStage s) const {
    return reached[index(m, k, s)];
  }

  // A copy of the calling thread's counters.
  static PredicateCounters read();
  // Zeroes the calling thread's counters.
  static void reset();
  // Records that a call of (m, k) entered stage s; no-op unless enabled.
  static void count(PredicateMethod m, PredicateKind k, PredicateStage s);
};

namespace detail {
// thread_local: predicates run concurrently in experiments; each thread counts its own.
inline thread_local PredicateCounters this_thread_predicate_counters;
}  // namespace detail

inline PredicateCounters PredicateCounters::read() { return detail::this_thread_predicate_counters; }

inline void PredicateCounters::reset() { detail::this_thread_predicate_counters = PredicateCounters{}; }

inline void PredicateCounters::count([[maybe_unused]] PredicateMethod m,
                                     [[maybe_unused]] PredicateKind k,
                                     [[maybe_unused]] PredicateStage s) {
  if constexpr (enabled) ++detail::this_thread_predicate_counters.reached[index(m, k, s)];
}

}  // namespace mk
