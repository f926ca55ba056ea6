// overlay_phases WORKLOAD N [OP] [KERNEL] [REPEAT]: where the time of one mkbool operation
// goes, step by step (the trace hook between the steps of boolean_op), then the assembly of
// the result into polygons with holes and the rest of the conversion to mk::Output. Prints
// one JSON line with the median milliseconds of each phase over REPEAT runs (default 5).
// overlay_phases --wkt WORKLOAD N A.wkt B.wkt writes the workload's two inputs as WKT
// MULTIPOLYGONs instead, for timing the command on them.
// [MK89 §3.1] (the steps) [BRIEF §6]
// Preconditions: built in Release; KERNEL is exact (default), rational or double.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "arithmetic/kernels/double_kernel.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "bench/workloads.hpp"
#include "core/assemble.hpp"
#include "core/boolean_op.hpp"
#include "core/to_output.hpp"

namespace {

using Clock = std::chrono::steady_clock;

const char* step_name(mk::Step s) {
  switch (s) {
    case mk::Step::prepared: return "prepare";
    case mk::Step::oriented: return "step1_orient";
    case mk::Step::vertex_rings: return "step2_rings";
    case mk::Step::intersections: return "step3_crossings";
    case mk::Step::classified: return "step4_classify";
    case mk::Step::selected: return "step5_select";
    case mk::Step::constructed: return "step6_construct";
  }
  return "?";
}

template <mk::Kernel K>
void run(const mk::bench::Workload& w, mk::Operation op, int repeat, unsigned threads) {
  const auto a = mk::to_kernel_polygon<K>(w.a);
  const auto b = mk::to_kernel_polygon<K>(w.b);
  std::map<std::string, std::vector<double>> ms;
  std::vector<std::string> order;
  const auto record = [&](const std::string& name, double value) {
    if (!ms.count(name)) order.push_back(name);
    ms[name].push_back(value);
  };
  std::size_t crossings = 0, out_vertices = 0, cycles = 0, polygons = 0, holes = 0;
  for (int r = 0; r < repeat; ++r) {
    Clock::time_point last = Clock::now();
    const Clock::time_point start = last;
    const mk::TraceHook<K> hook = [&](mk::Step s, const mk::Arrangement<K>&) {
      const Clock::time_point now = Clock::now();
      record(step_name(s), std::chrono::duration<double, std::milli>(now - last).count());
      last = now;
    };
    mk::Options options{op, true, mk::EfOrganisation::hash, mk::PairSearch::sweep};
    options.threads = threads;
    const mk::BooleanResult<K> res = mk::boolean_op<K>(a, b, options, hook);
    const Clock::time_point done = Clock::now();
    record("boolean_op", std::chrono::duration<double, std::milli>(done - start).count());
    const std::vector<int> parent = mk::inclusion_parents(res.arrangement, res.cycles);
    const Clock::time_point assembled = Clock::now();
    record("assembly", std::chrono::duration<double, std::milli>(assembled - done).count());
    const mk::Output out = mk::to_output<K, mk::ExactKernel>(res, false, threads);  // as mk::compute by default
    record("to_output", std::chrono::duration<double, std::milli>(Clock::now() - assembled).count());
    crossings = res.stats.crossings;
    out_vertices = res.stats.vertices_out;
    cycles = res.cycles.size();
    polygons = out.polygons.size();
    holes = 0;
    for (const auto& p : out.polygons) holes += p.holes.size();
    (void)parent;
  }
  std::printf("{\"workload\":\"%s\",\"n\":%zu,\"op\":\"%s\",\"kernel\":\"%s\",\"threads\":%u,\"vertices_in\":%zu,"
              "\"crossings\":%zu,\"vertices_out\":%zu,\"cycles\":%zu,\"polygons\":%zu,\"holes\":%zu",
              std::string(mk::bench::workload_name(w.kind)).c_str(), w.n, std::string(mk::operation_name(op)).c_str(),
              std::string(K::name).c_str(), threads, w.vertices(), crossings, out_vertices, cycles, polygons, holes);
  for (const auto& name : order) {
    auto& v = ms[name];
    std::sort(v.begin(), v.end());
    std::printf(",\"%s\":%.2f", name.c_str(), v[v.size() / 2]);
  }
  std::printf("}\n");
}

// Writes mp as one WKT MULTIPOLYGON (rings closed, shortest round-trip doubles).
bool write_wkt(const mk::MultiPolygon& mp, const char* path) {
  std::FILE* f = std::fopen(path, "w");
  if (!f) return false;
  const auto ring = [&](const mk::Ring& r) {
    std::fputc('(', f);
    for (std::size_t i = 0; i <= r.size(); ++i) {
      const mk::Point& q = r[i % r.size()];
      std::fprintf(f, "%s%.17g %.17g", i ? "," : "", q.x, q.y);
    }
    std::fputc(')', f);
  };
  std::fputs("MULTIPOLYGON(", f);
  for (std::size_t p = 0; p < mp.size(); ++p) {
    std::fputs(p ? ",(" : "(", f);
    ring(mp[p].shell);
    for (const auto& h : mp[p].holes) std::fputc(',', f), ring(h);
    std::fputc(')', f);
  }
  std::fputs(")\n", f);
  return std::fclose(f) == 0;
}

[[noreturn]] void usage(const std::string& message) {
  std::cerr << "overlay_phases: " << message
            << "\nusage: overlay_phases WORKLOAD N [OP] [KERNEL] [REPEAT] [THREADS]\n"
            << "       overlay_phases --wkt WORKLOAD N A.wkt B.wkt\n";
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 6 && std::string(argv[1]) == "--wkt") {
    const auto kind = mk::bench::workload_named(argv[2]);
    if (!kind) usage(std::string("unknown workload '") + argv[2] + "'");
    const std::size_t n = std::strtoull(argv[3], nullptr, 10);
    if (n < 1) usage("N must be positive");
    const mk::bench::Workload w = mk::bench::make_workload(*kind, n);
    if (!write_wkt(w.a_ogc, argv[4]) || !write_wkt(w.b_ogc, argv[5])) {
      std::cerr << "overlay_phases: cannot write " << argv[4] << " or " << argv[5] << "\n";
      return 1;
    }
    return 0;
  }
  if (argc < 3) usage("WORKLOAD and N are required");
  const auto kind = mk::bench::workload_named(argv[1]);
  if (!kind) usage(std::string("unknown workload '") + argv[1] + "'");
  const std::size_t n = std::strtoull(argv[2], nullptr, 10);
  if (n < 1) usage("N must be positive");
  mk::Operation op = mk::Operation::intersection;
  if (argc > 3) {
    const std::string name = argv[3];
    bool found = false;
    for (const auto o : {mk::Operation::intersection, mk::Operation::union_, mk::Operation::difference,
                         mk::Operation::symmetric_difference}) {
      if (mk::operation_name(o) == name) op = o, found = true;
    }
    if (!found) usage("unknown operation '" + name + "'");
  }
  const std::string kernel = argc > 4 ? argv[4] : "exact";
  const int repeat = argc > 5 ? std::atoi(argv[5]) : 5;
  const unsigned threads = argc > 6 ? static_cast<unsigned>(std::atoi(argv[6])) : 0;
  if (repeat < 1) usage("REPEAT must be positive");
  const mk::bench::Workload w = mk::bench::make_workload(*kind, n);
  try {
    if (kernel == "exact") {
      run<mk::ExactKernel>(w, op, repeat, threads);
    } else if (kernel == "rational") {
      run<mk::RationalKernel>(w, op, repeat, threads);
    } else if (kernel == "double") {
      run<mk::DoubleKernel>(w, op, repeat, threads);
    } else {
      usage("unknown kernel '" + kernel + "' (exact, rational, double)");
    }
  } catch (const std::exception& e) {
    std::cerr << "overlay_phases: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
