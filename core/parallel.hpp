// Independent tasks run on several threads: the phases of the operation that split into
// parts that do not write to the same memory (the two polygons, slabs of the sweep, cycles).
// [BRIEF §6] (across cores)
// Preconditions: tasks do not depend on each other's results; whatever they write is
// disjoint. Results never depend on the number of threads: callers split work into parts
// fixed by the input alone and combine them in the parts' order.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace mk {

// The number of threads to use when `requested` is 0 (every core), at least 1.
inline unsigned resolve_threads(unsigned requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? hw : 1;
}

// Below this much work (items such as edges or points), a phase runs on one thread: starting
// threads costs tens of microseconds.
inline constexpr std::size_t kParallelWork = 16384;

// Threads for a phase of `work` items.
inline unsigned threads_for(std::size_t work, unsigned threads) {
  return work < kParallelWork ? 1 : std::max(1u, threads);
}

// Calls f(i) for every i in [0, tasks), on up to `threads` threads (the caller's included),
// each taking the next task not started. If tasks throw, the exception of the lowest task
// index is rethrown once all have ended, as a loop would have thrown it first.
template <class F>
void run_tasks(unsigned threads, std::size_t tasks, F&& f) {
  const std::size_t workers = std::min<std::size_t>(std::max(1u, threads), tasks);
  if (workers <= 1) {
    for (std::size_t i = 0; i < tasks; ++i) f(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(tasks);
  const auto work = [&] {
    for (std::size_t i = next++; i < tasks; i = next++) {
      try {
        f(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

// Calls f(begin, end) over consecutive blocks of [0, n), `parts` blocks fixed by the caller
// (so that per-block results combine the same way on any number of threads).
template <class F>
void run_blocks(unsigned threads, std::size_t n, std::size_t parts, F&& f) {
  parts = std::max<std::size_t>(1, std::min(parts, n));
  run_tasks(threads, parts, [&](std::size_t i) { f(n * i / parts, n * (i + 1) / parts); });
}

}  // namespace mk
