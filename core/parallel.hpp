// Independent tasks run on several threads: the phases of the operation that split into
// parts that do not write to the same memory (the two polygons, slabs of the sweep, cycles).
// [BRIEF §6] (across cores)
// Preconditions: tasks do not depend on each other's results; whatever they write is
// disjoint. Results never depend on the number of threads: callers split work into parts
// fixed by the input alone and combine them in the parts' order.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include <unistd.h>

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

namespace detail {

// Threads kept from one phase to the next: starting and joining two threads costs 35-45 us
// here, and an operation has about twenty phases that run on threads (half a millisecond on
// blob 10^5's 11 ms); waking threads that wait costs a few. One batch at a time: a caller
// that finds the pool busy (another thread's operation), that is one of the pool's threads
// or inside a batch of its own (nested phases), or that runs in a process forked after the
// pool was made (whose threads the child does not have) is told no, and starts threads of
// its own.
class ThreadPool {
 public:
  // The process's pool, never destroyed: its threads wait until the process ends, and
  // static destructors must not pull it away from them.
  static ThreadPool& instance() {
    static ThreadPool* const pool = new ThreadPool();
    return *pool;
  }

  // Runs job(context) on the calling thread and on `helpers` of the pool's threads (made when
  // first needed), and returns when all have returned; false, having run nothing, when the
  // pool cannot take it. The job must not throw.
  bool run(std::size_t helpers, void (*job)(void*), void* context) {
    if (inside() || getpid() != pid_) return false;
    std::unique_lock batch(batch_, std::try_to_lock);
    if (!batch.owns_lock()) return false;
    {
      std::lock_guard lock(m_);
      try {
        while (threads_.size() < helpers) {
          const std::size_t index = threads_.size();
          threads_.emplace_back([this, index] { serve(index); });
        }
      } catch (...) {  // no more threads to be had: the batch runs on those there are
        helpers = threads_.size();
      }
      job_ = job;
      context_ = context;
      wanted_ = helpers;
      pending_ = helpers;
      ++generation_;
    }
    wake_.notify_all();
    inside() = true;
    job(context);
    inside() = false;
    std::unique_lock lock(m_);
    done_.wait(lock, [&] { return pending_ == 0; });
    return true;
  }

 private:
  ThreadPool() : pid_(getpid()) {}
  // Whether this thread is one of the pool's or is running a batch.
  static bool& inside() {
    thread_local bool flag = false;
    return flag;
  }
  // Thread `index` runs every batch that wants it, once.
  void serve(std::size_t index) {
    inside() = true;
    std::uint64_t seen = 0;
    std::unique_lock lock(m_);
    for (;;) {
      wake_.wait(lock, [&] { return generation_ != seen && index < wanted_; });
      seen = generation_;
      void (*const job)(void*) = job_;
      void* const context = context_;
      lock.unlock();
      job(context);
      lock.lock();
      if (--pending_ == 0) done_.notify_all();
    }
  }

  const pid_t pid_;
  std::mutex batch_;  // held by the caller for the whole batch
  std::mutex m_;      // guards what follows
  std::condition_variable wake_, done_;
  std::vector<std::thread> threads_;
  void (*job_)(void*) = nullptr;
  void* context_ = nullptr;
  std::size_t wanted_ = 0, pending_ = 0;
  std::uint64_t generation_ = 0;
};

}  // namespace detail

// Calls f(i) for every i in [0, tasks), on up to `threads` threads (the caller's included),
// each taking the next task not started: the pool's threads (detail::ThreadPool), or threads
// started for the call when the pool cannot take it. If tasks throw, the exception of the
// lowest task index is rethrown once all have ended, as a loop would have thrown it first.
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
  using Work = decltype(work);
  const auto call = [](void* context) { (*static_cast<const Work*>(context))(); };
  if (!detail::ThreadPool::instance().run(workers - 1, call, const_cast<void*>(static_cast<const void*>(&work)))) {
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
  }
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
