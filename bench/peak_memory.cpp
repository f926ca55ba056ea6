// peak_memory [WORKLOAD] [N] [KERNEL]: the peak memory of one mkbool intersection through the
// public API (mk::compute, result polygons included), per input vertex. Prints one JSON line.
// WORKLOAD is any workload of bench/workloads.hpp (default blob); N the size argument of
// bench/workloads.hpp (default 1000000); KERNEL any of mk::kernel_names() (default: the
// default kernel). [BRIEF §6] (memory: at most 256 bytes per input vertex at n = 1e6)
//
// How it measures: the generated inputs stay in memory during the operation, so the
// operation's own peak is the process's peak resident set (getrusage's ru_maxrss, which the
// kernel keeps as a high-water mark) minus the resident set just before the call
// (/proc/self/statm). The generator's temporary copies are freed before that reading.
// Preconditions: Linux (/proc/self/statm).
#include <sys/resource.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <string_view>

#include "api/mkbool.hpp"
#include "bench/workloads.hpp"

namespace {

long resident_kib() {
  std::ifstream statm("/proc/self/statm");
  long size = 0;
  long resident = 0;
  statm >> size >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

long peak_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

[[noreturn]] void usage_error(const std::string& message) {
  std::cerr << "peak_memory: error: " << message << " (usage: peak_memory [WORKLOAD] [N] [KERNEL])\n";
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string workload = argc > 1 ? argv[1] : "blob";
  const auto kind = mk::bench::workload_named(workload);
  if (!kind) {
    std::string known;
    for (const auto k : mk::bench::all_workload_kinds) known += (known.empty() ? "" : ", ") + std::string(mk::bench::workload_name(k));
    usage_error("unknown workload '" + workload + "' (" + known + ")");
  }
  std::size_t n = 1000000;
  if (argc > 2) {
    const std::string_view text = argv[2];
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc{} || end != text.data() + text.size() || n < 3 || n > 10000000) {
      usage_error("N must be a whole number from 3 to 10000000, not '" + std::string(text) + "'");
    }
  }
  mk::BooleanOptions options;
  options.kernel = argc > 3 ? argv[3] : std::string(mk::default_kernel());
  {
    std::string known;
    bool built = false;
    for (const auto k : mk::kernel_names()) {
      built = built || k == options.kernel;
      known += (known.empty() ? "" : ", ") + std::string(k);
    }
    if (!built) usage_error("unknown kernel '" + options.kernel + "' (built: " + known + ")");
  }
  if (argc > 4) usage_error("unexpected argument '" + std::string(argv[4]) + "'");
  options.area = false;
  mk::Polygon a;
  mk::Polygon b;
  {
    mk::bench::Workload w = mk::bench::make_workload(*kind, n);
    a = std::move(w.a);
    b = std::move(w.b);
  }  // the peers' copies of the input are freed here
  const std::size_t vertices = [&] {
    std::size_t v = 0;
    for (const auto* p : {&a, &b}) {
      for (const auto& ring : p->rings) v += ring.size();
    }
    return v;
  }();
  const long before = resident_kib();
  try {
    const mk::BooleanOutput out = mk::compute(a, b, options);
    const long peak = peak_kib();
    const double op_bytes = static_cast<double>(peak - before) * 1024.0;
    const double all_bytes = static_cast<double>(peak) * 1024.0;
    std::printf(
        "{\"workload\":\"%s\",\"n\":%zu,\"kernel\":\"%s\",\"vertices_in\":%zu,\"vertices_out\":%zu,"
        "\"op_ms\":%.1f,\"peak_rss_mib\":%.1f,\"before_op_mib\":%.1f,\"op_bytes_per_vertex\":%.1f,"
        "\"process_bytes_per_vertex\":%.1f}\n",
        workload.c_str(), n, out.stats.kernel.c_str(), vertices, out.stats.vertices_out,
        static_cast<double>(out.stats.op_ns) / 1e6, static_cast<double>(peak) / 1024.0,
        static_cast<double>(before) / 1024.0, op_bytes / static_cast<double>(vertices),
        all_bytes / static_cast<double>(vertices));
  } catch (const std::exception& e) {
    std::cerr << "peak_memory: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
