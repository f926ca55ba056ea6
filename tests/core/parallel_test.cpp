// Tasks on threads: every task runs once, on the process's pool of waiting threads or on
// threads started for the call (nested calls, concurrent callers, a forked child), and the
// error of the lowest task is the one rethrown.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "core/parallel.hpp"

namespace mk {
namespace {

// How many times each of `tasks` tasks ran in one call on `threads` threads.
std::vector<int> runs_per_task(unsigned threads, std::size_t tasks) {
  std::vector<std::atomic<int>> count(tasks);
  run_tasks(threads, tasks, [&](std::size_t i) { ++count[i]; });
  std::vector<int> out;
  for (const auto& c : count) out.push_back(c.load());
  return out;
}

TEST(RunTasks, EveryTaskOnceOnAnyNumberOfThreads) {
  for (int round = 0; round < 50; ++round) {
    for (const unsigned threads : {1u, 2u, 3u, 5u}) {
      for (const std::size_t tasks : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{40}}) {
        EXPECT_EQ(runs_per_task(threads, tasks), std::vector<int>(tasks, 1)) << threads << " threads, " << tasks << " tasks";
      }
    }
  }
}

TEST(RunTasks, TheLowestTasksErrorIsRethrown) {
  for (const unsigned threads : {1u, 2u, 4u}) {
    std::atomic<int> ran{0};
    try {
      run_tasks(threads, 20, [&](std::size_t i) {
        ++ran;
        if (i == 13 || i == 6) throw std::runtime_error("task " + std::to_string(i));
      });
      ADD_FAILURE() << "nothing thrown";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "task 6");
    }
    EXPECT_EQ(ran.load(), threads == 1 ? 7 : 20);  // one thread stops where a loop would
  }
}

TEST(RunTasks, NestedCallsRunEveryTask) {
  std::vector<std::atomic<int>> count(6 * 9);
  run_tasks(2, 6, [&](std::size_t i) { run_tasks(2, 9, [&](std::size_t j) { ++count[9 * i + j]; }); });
  for (const auto& c : count) EXPECT_EQ(c.load(), 1);
}

// Several callers at once: one has the pool, the others start threads of their own.
TEST(RunTasks, ConcurrentCallersEachRunTheirTasks) {
  std::vector<std::thread> callers;
  std::vector<int> wrong(4, 0);
  for (int c = 0; c < 4; ++c) {
    callers.emplace_back([&, c] {
      for (int round = 0; round < 200; ++round) {
        std::atomic<long> sum{0};
        run_tasks(2, 16, [&](std::size_t i) { sum += static_cast<long>(i); });
        if (sum.load() != 120) ++wrong[static_cast<std::size_t>(c)];
      }
    });
  }
  for (auto& t : callers) t.join();
  EXPECT_EQ(wrong, std::vector<int>(4, 0));
}

// A child forked after the pool was made has none of its threads: its calls must not wait
// for them (the child ends itself after 20 s if they do).
TEST(RunTasks, AForkedChildRunsItsTasks) {
  EXPECT_EQ(runs_per_task(2, 8), std::vector<int>(8, 1));  // the pool exists
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    alarm(20);
    std::atomic<long> sum{0};
    run_tasks(2, 16, [&](std::size_t i) { sum += static_cast<long>(i); });
    _exit(sum.load() == 120 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child did not end by itself";
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace mk
