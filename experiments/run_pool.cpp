// The worker pool: forked workers take cases from the parent over pipes and announce each
// run before starting it, so that when a worker dies (crash) or overruns the time limit
// (killed: timeout) the parent knows which run it was, records it, and restarts a worker
// at the next run. [MK89 §3.3] (rounded arithmetic can fail in any way; a sweep must not)
// Preconditions: single-threaded parent (fork without exec).
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <stdexcept>

#include "experiments/generators.hpp"
#include "experiments/operations.hpp"
#include "experiments/runner.hpp"

namespace mk::experiments {

namespace {

using Clock = std::chrono::steady_clock;

bool write_all(int fd, const std::string& s) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// In a worker: when the parent is gone there is nobody left to report to.
void report(int fd, const std::string& s) {
  if (!write_all(fd, s)) _exit(3);
}

struct Worker {
  pid_t pid = -1;
  int to_worker = -1;    // parent writes assignments
  int from_worker = -1;  // parent reads announcements and rows
  std::string buffer;
  bool busy = false;
  bool generating = false;  // building the case, before its first run
  std::size_t case_size = 0;
  std::size_t case_pos = 0;
  std::size_t slot = 0;
  Clock::time_point slot_start;
  bool killed_for_timeout = false;
};

// Worker side: read "case_pos first_slot" lines, answer "S slot", "R row", "D".
[[noreturn]] void worker_main(int in_fd, int out_fd, const std::vector<IndexedCase>& cases, const RunOptions& o) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive a killed parent
  if (o.memory_mb > 0) {
    const rlim_t bytes = static_cast<rlim_t>(o.memory_mb) << 20;
    const rlimit lim{bytes, bytes};
    setrlimit(RLIMIT_AS, &lim);  // a runaway allocation becomes std::bad_alloc: an error row
  }
  FILE* in = fdopen(in_fd, "r");
  char line[128];
  while (in != nullptr && std::fgets(line, sizeof line, in) != nullptr) {
    std::size_t pos = 0, first = 0;
    if (std::sscanf(line, "%zu %zu", &pos, &first) != 2 || pos >= cases.size()) _exit(4);
    run_case(
        cases[pos], o, first, [&](std::size_t slot) { report(out_fd, "S " + std::to_string(slot) + "\n"); },
        [&](const ResultRow& r) { report(out_fd, "R " + to_csv(r) + "\n"); },
        [&](std::size_t size) { report(out_fd, "Z " + std::to_string(size) + "\n"); });
    report(out_fd, "D\n");
  }
  _exit(0);
}

class Pool {
 public:
  Pool(const std::vector<IndexedCase>& cases, const RunOptions& o, std::ofstream* partial)
      : cases_(cases), o_(o), partial_(partial), slots_(slot_count(o)) {
    // Largest cases first, so that the last ones to finish are short and every worker
    // stays busy to the end (the plan's order and case indices are unchanged).
    std::vector<std::size_t> order(cases.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return cases[x].spec.param("n", 0) > cases[y].spec.param("n", 0);
    });
    for (const std::size_t i : order) queue_.push_back({i, 0});
  }

  std::vector<std::pair<std::pair<std::size_t, std::size_t>, ResultRow>> run() {
    const int jobs = std::max(1, std::min<int>(o_.jobs, static_cast<int>(cases_.size())));
    workers_.resize(static_cast<std::size_t>(jobs));
    for (auto& w : workers_) {
      if (!queue_.empty()) start(w);
    }
    start_time_ = last_progress_ = Clock::now();
    while (done_ < cases_.size()) {
      std::vector<pollfd> fds;
      std::vector<Worker*> owners;
      for (auto& w : workers_) {
        if (w.from_worker >= 0) {
          fds.push_back({w.from_worker, POLLIN, 0});
          owners.push_back(&w);
        }
      }
      if (fds.empty()) throw std::logic_error("run_sweep: no worker left with cases pending");
      ::poll(fds.data(), fds.size(), 100);
      for (std::size_t i = 0; i < fds.size(); ++i) {
        if (fds[i].revents != 0) read_from(*owners[i]);
      }
      const auto now = Clock::now();
      for (auto& w : workers_) {
        if (w.busy && !w.killed_for_timeout && std::chrono::duration<double>(now - w.slot_start).count() > o_.timeout_seconds) {
          w.killed_for_timeout = true;
          ::kill(w.pid, SIGKILL);  // its pipe then reports end of file: handled in read_from
        }
      }
      if (o_.progress && now - last_progress_ > std::chrono::milliseconds(250)) print_progress(now);
    }
    for (auto& w : workers_) stop(w);
    if (o_.progress) {
      print_progress(Clock::now());
      std::fputc('\n', stderr);
    }
    return std::move(rows_);
  }

 private:
  void start(Worker& w) {
    const auto [pos, first] = queue_.front();
    queue_.pop_front();
    int to[2], from[2];
    if (::pipe(to) != 0 || ::pipe(from) != 0) throw std::runtime_error("pipe: " + std::string(std::strerror(errno)));
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork: " + std::string(std::strerror(errno)));
    if (pid == 0) {
      // Hold no other worker's pipe ends, or their deaths would not show as end of file.
      for (const auto& other : workers_) {
        if (other.to_worker >= 0) ::close(other.to_worker);
        if (other.from_worker >= 0) ::close(other.from_worker);
      }
      ::close(to[1]);
      ::close(from[0]);
      worker_main(to[0], from[1], cases_, o_);
    }
    ::close(to[0]);
    ::close(from[1]);
    ::fcntl(to[1], F_SETFD, FD_CLOEXEC);
    ::fcntl(from[0], F_SETFD, FD_CLOEXEC);
    w = Worker{};
    w.pid = pid;
    w.to_worker = to[1];
    w.from_worker = from[0];
    assign(w, pos, first);
  }

  void assign(Worker& w, std::size_t pos, std::size_t first) {
    w.busy = true;
    w.generating = true;
    w.case_size = 0;
    w.case_pos = pos;
    w.slot = first;
    w.slot_start = Clock::now();
    // A failed write means the worker just died; its end of file comes next.
    write_all(w.to_worker, std::to_string(pos) + " " + std::to_string(first) + "\n");
  }

  void stop(Worker& w) {
    if (w.to_worker >= 0) ::close(w.to_worker);
    if (w.from_worker >= 0) ::close(w.from_worker);
    if (w.pid > 0) ::waitpid(w.pid, nullptr, 0);
    w = Worker{};
  }

  void read_from(Worker& w) {
    char buf[65536];
    const ssize_t n = ::read(w.from_worker, buf, sizeof buf);
    if (n > 0) {
      w.buffer.append(buf, static_cast<std::size_t>(n));
      std::size_t nl;
      while ((nl = w.buffer.find('\n')) != std::string::npos) {
        const std::string line = w.buffer.substr(0, nl);
        w.buffer.erase(0, nl + 1);
        handle_line(w, line);
      }
      return;
    }
    if (n < 0 && errno == EINTR) return;
    died(w);
  }

  void handle_line(Worker& w, const std::string& line) {
    if (line.rfind("S ", 0) == 0) {
      w.slot = std::stoul(line.substr(2));
      w.slot_start = Clock::now();
    } else if (line.rfind("Z ", 0) == 0) {
      w.generating = false;
      w.case_size = std::stoul(line.substr(2));
    } else if (line.rfind("R ", 0) == 0) {
      add_row(w.case_pos, w.slot, parse_csv_row(line.substr(2)));
    } else if (line == "D") {
      finish_case(w);
    }
  }

  void finish_case(Worker& w) {
    ++done_;
    w.busy = false;
    if (w.killed_for_timeout) return;  // finished just as it was killed: restarted in died()
    if (queue_.empty()) {
      stop(w);
      return;
    }
    const auto [pos, first] = queue_.front();
    queue_.pop_front();
    assign(w, pos, first);
  }

  // The worker's pipe closed: it exited, crashed or was killed for its time limit.
  void died(Worker& w) {
    int status = 0;
    ::waitpid(w.pid, &status, 0);
    ::close(w.to_worker);
    ::close(w.from_worker);
    const bool was_busy = w.busy;
    const std::size_t pos = w.case_pos, slot = w.slot;
    const bool timed_out = w.killed_for_timeout, generating = w.generating;
    const std::size_t size = w.case_size;
    w = Worker{};
    if (was_busy) record_failure(pos, slot, timed_out, status, generating, size);
    if (!queue_.empty()) start(w);
  }

  void record_failure(std::size_t pos, std::size_t slot, bool timed_out, int status, bool generating, std::size_t size) {
    const IndexedCase& c = cases_[pos];
    ResultRow r;
    r.case_index = c.index;
    r.generator = c.spec.generator;
    r.variant = c.spec.variant;
    r.params = c.spec.params_text();
    r.seed = c.spec.seed;
    r.size = size;
    const std::size_t per_group = 1 + o_.kernels.size();
    const std::size_t g = slot / per_group, in_group = slot % per_group;
    r.op = run_operation_name(c.spec, o_.ops[g / o_.regular.size()]);
    r.regular = o_.regular[g % o_.regular.size()];
    r.kernel = in_group == 0 ? "reference" : o_.kernels[in_group - 1];
    r.verdict = timed_out ? Verdict::timeout : Verdict::crash;
    if (timed_out) {
      r.message = "killed after " + std::to_string(o_.timeout_seconds) + " s";
    } else if (WIFSIGNALED(status)) {
      r.message = "signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
    } else {
      r.message = "worker exited with status " + std::to_string(WEXITSTATUS(status));
    }
    if (generating) {
      // The generator itself failed: the case has no runs to resume (a generator bug).
      r.kernel = "reference";
      r.message = "while generating the case: " + r.message;
      add_row(pos, slot, r);
      ++done_;
      return;
    }
    add_row(pos, slot, r);
    // Resume after the failed run: the next kernel, or the next group after a reference.
    const std::size_t next = in_group == 0 ? (g + 1) * per_group : slot + 1;
    if (next < slots_) queue_.push_front({pos, next});
    else ++done_;
  }

  void add_row(std::size_t pos, std::size_t slot, ResultRow r) {
    if (partial_ != nullptr) *partial_ << to_csv(r) << '\n' << std::flush;
    rows_.push_back({{pos, slot}, std::move(r)});
  }

  void print_progress(Clock::time_point now) {
    last_progress_ = now;
    const double t = std::chrono::duration<double>(now - start_time_).count();
    const double rate = t > 0 ? static_cast<double>(rows_.size()) / t : 0;
    const double left = done_ > 0 ? t * static_cast<double>(cases_.size() - done_) / static_cast<double>(done_) : 0;
    std::fprintf(stderr, "\r  %zu/%zu cases, %zu runs, %.0f runs/s, %.0f s elapsed, ETA %.0f s   ", done_,
                 cases_.size(), rows_.size(), rate, t, left);
  }

  const std::vector<IndexedCase>& cases_;
  const RunOptions& o_;
  std::ofstream* partial_;
  const std::size_t slots_;
  std::deque<std::pair<std::size_t, std::size_t>> queue_;  // (case position, first slot)
  std::vector<Worker> workers_;
  std::size_t done_ = 0;
  std::vector<std::pair<std::pair<std::size_t, std::size_t>, ResultRow>> rows_;
  Clock::time_point start_time_, last_progress_;
};

}  // namespace

std::vector<ResultRow> run_sweep(const std::vector<IndexedCase>& cases, const RunOptions& o,
                                 const std::string& partial_csv, SweepStats* stats) {
  const auto t0 = Clock::now();
  std::ofstream partial;
  if (!partial_csv.empty()) {
    partial.open(partial_csv);
    partial << csv_header() << '\n';
  }
  std::vector<std::pair<std::pair<std::size_t, std::size_t>, ResultRow>> keyed;
  if (cases.empty()) {
  } else if (o.isolate) {
    ::signal(SIGPIPE, SIG_IGN);  // a dead worker's pipe must give EPIPE, not kill the parent
    Pool pool(cases, o, partial_csv.empty() ? nullptr : &partial);
    keyed = pool.run();
  } else {
    for (std::size_t pos = 0; pos < cases.size(); ++pos) {
      std::size_t slot = 0;
      run_case(
          cases[pos], o, 0, [&](std::size_t s) { slot = s; },
          [&](const ResultRow& r) {
            if (partial.is_open()) partial << to_csv(r) << '\n';
            keyed.push_back({{pos, slot}, r});
          });
    }
  }
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<ResultRow> rows;
  for (auto& k : keyed) rows.push_back(std::move(k.second));
  fill_oracle_agreement(rows);
  if (stats != nullptr) {
    stats->cases = cases.size();
    stats->rows = rows.size();
    stats->seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  return rows;
}

}  // namespace mk::experiments
