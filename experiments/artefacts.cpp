// Failure artefacts: regression case files (regression_case.cpp) and SVG pictures, and
// pictures of snapped results, each made in a forked child with a time limit (the kernel
// runs again to draw its output). [MK89 §3.3] [Ho99]
// Preconditions: see artefacts.hpp.
#include "experiments/artefacts.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <thread>

#include "api/mkbool.hpp"
#include "core/error.hpp"
#include "experiments/generators.hpp"
#include "experiments/operations.hpp"
#include "experiments/peer_verdict.hpp"
#include "experiments/snapping_pictures.hpp"
#include "experiments/verdict.hpp"

namespace mk::experiments {

namespace fs = std::filesystem;

Operation parse_operation(const std::string& name) {
  for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                             Operation::symmetric_difference}) {
    if (operation_name(op) == name) return op;
  }
  throw std::invalid_argument("unknown operation '" + name + "' (intersection, union, difference, xor)");
}

std::string_view artefact_kind_name(Artefact::Kind kind) {
  switch (kind) {
    case Artefact::Kind::regression_case: return "regression_case";
    case Artefact::Kind::picture: return "picture";
    case Artefact::Kind::snapping: return "snapping";
  }
  return "?";
}

std::optional<Artefact::Kind> parse_artefact_kind(std::string_view name) {
  for (const auto k : {Artefact::Kind::regression_case, Artefact::Kind::picture, Artefact::Kind::snapping}) {
    if (artefact_kind_name(k) == name) return k;
  }
  return std::nullopt;
}

namespace {

// Runs f in a forked child, killing it after `timeout` seconds. True when it finished.
bool run_isolated(const std::function<void()>& f, double timeout) {
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return false;
  if (pid == 0) {
    try {
      f();
    } catch (...) {
      _exit(1);
    }
    _exit(0);
  }
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

CaseSpec spec_of(const ResultRow& r) { return {r.generator, r.variant, parse_params(r.params), r.seed}; }

// Every regression case a sweep writes says how it becomes a test.
const std::string kKeepAsTest =
    "to keep it as a test: copy this file to tests/regression/cases/ (tests/regression replays every case there)";

std::string run_suffix(const ResultRow& r) { return "_" + r.op + (r.regular ? "" : "_nonregular"); }

// Which failures to picture first: the worst, and among valid outputs those whose area
// error shows a wrong decision rather than a crossing point rounded differently.
int severity(const ResultRow& r) {
  switch (r.verdict) {
    case Verdict::crash: return 0;
    case Verdict::timeout: return 1;
    case Verdict::invalid_output: return 2;
    case Verdict::error:
    case Verdict::exception: return 3;
    case Verdict::wrong: return 4;
    default: return r.area_error && *r.area_error > 1e-12 ? 4 : 5;
  }
}

}  // namespace

std::vector<Artefact> write_artefacts(const std::vector<ResultRow>& rows, const std::string& dir,
                                      const ArtefactOptions& options) {
  // Exact kernels (and the reference itself): every failure, as a regression case.
  // Inexact kernels: the smallest failures of each (kernel, generator), worst verdicts first.
  std::vector<const ResultRow*> exact_failures;
  std::map<std::pair<std::string, std::string>, std::vector<const ResultRow*>> inexact;
  for (const auto& r : rows) {
    if (!is_failure(r.verdict)) continue;
    if (r.kernel == "reference" || is_exact_kernel(r.kernel)) exact_failures.push_back(&r);
    else inexact[{r.kernel, r.generator}].push_back(&r);
  }
  std::vector<std::pair<Artefact::Kind, const ResultRow*>> todo;
  // A failed consistency check of the exact reference while measuring an area error: a
  // bug of the core, reproduced on double polygons where possible.
  std::vector<const ResultRow*> inconsistencies;
  std::set<std::uint64_t> inconsistent_cases;
  for (const auto& r : rows) {
    if (r.message.find("[reference inconsistency]") != std::string::npos && inconsistent_cases.insert(r.case_index).second) {
      inconsistencies.push_back(&r);
    }
  }
  for (const auto* r : exact_failures) {
    todo.push_back({Artefact::Kind::regression_case, r});
    todo.push_back({Artefact::Kind::picture, r});
  }
  for (auto& [key, list] : inexact) {
    std::stable_sort(list.begin(), list.end(), [](const ResultRow* x, const ResultRow* y) {
      if (severity(*x) != severity(*y)) return severity(*x) < severity(*y);
      if (x->size != y->size) return x->size < y->size;
      return x->case_index < y->case_index;
    });
    std::set<std::uint64_t> seen;  // one picture per case
    for (const ResultRow* r : list) {
      if (seen.size() >= options.pictures_per_group) break;
      if (seen.insert(r->case_index).second) todo.push_back({Artefact::Kind::picture, r});
    }
  }
  // Results that certified rounding snapped: the nearest doubles beside the snapped output.
  for (const ResultRow* r : snapped_runs_to_picture(rows, options.snapping_per_generator)) {
    todo.push_back({Artefact::Kind::snapping, r});
  }
  std::vector<Artefact> out;
  std::set<std::string> used_names;
  for (const auto& [kind, r] : todo) {
    const CaseSpec spec = spec_of(*r);
    Artefact art{kind, "", *r};
    if (kind == Artefact::Kind::regression_case) {
      std::string stem = r->generator + "_" + std::to_string(r->seed);
      if (!used_names.insert(stem).second) stem += run_suffix(*r);
      used_names.insert(stem);
      art.path = "regression/" + stem + ".wkt";
    } else if (kind == Artefact::Kind::snapping) {
      art.path = "pictures/snapping/" + spec.stem() + run_suffix(*r) + ".svg";
    } else {
      art.path = "pictures/" + r->kernel + "/" + spec.stem() + run_suffix(*r) + ".svg";
    }
    const fs::path target = fs::path(dir) / art.path;
    const bool ok = run_isolated(
        [&] {
          const Case c = make_case(spec);
          const Operation op = parse_run_operation(r->op);
          if (kind == Artefact::Kind::regression_case) {
            write_file(target, regression_case_text(c, op, r->regular,
                                                    {"generator=" + r->generator + " variant=" + r->variant +
                                                         " params=" + r->params + " seed=" + std::to_string(r->seed),
                                                     "kernel=" + r->kernel + " verdict=" +
                                                         std::string(verdict_name(r->verdict)) + " " + r->message,
                                                     kKeepAsTest}));
            return;
          }
          if (kind == Artefact::Kind::snapping) {
            write_file(target, snapping_picture(c, op, r->regular, r->kernel));
            return;
          }
          const ExactResult ref = case_reference(c, op, r->regular, false);
          std::optional<Output> kernel_out;
          std::string title = r->kernel + ": " + std::string(verdict_name(r->verdict));
          if (r->area_error) {
            char buf[48];
            std::snprintf(buf, sizeof buf, ", area error %.2g", *r->area_error);
            title += buf;
          }
          const bool rerun = r->kernel != "reference" && r->verdict != Verdict::crash && r->verdict != Verdict::timeout;
          if (rerun) {
            try {
              kernel_out = is_peer(r->kernel) ? peer_as_output(run_peer_on_case(r->kernel, c, op))
                                              : run_operation(c, BooleanOptions{op, r->regular, r->kernel}).output;
            } catch (const std::exception& e) {
              title += " (" + std::string(e.what()).substr(0, 80) + ")";
            }
          } else {
            title += " (no output)";
          }
          const std::string exact_title = "A, B and the exact " + r->op + (r->regular ? "" : " (non-regular)") +
                                          ": " + std::to_string(ref.cycles.size()) + " polygons";
          write_file(target, failure_picture(c.a, c.b, ref.output, exact_title, kernel_out, title));
        },
        options.timeout_seconds);
    if (ok && fs::exists(target)) out.push_back(std::move(art));
  }
  for (const ResultRow* r : inconsistencies) {
    Artefact art{Artefact::Kind::regression_case, "regression/inconsistency_" + r->generator + "_" + std::to_string(r->seed) + ".wkt", *r};
    const fs::path target = fs::path(dir) / art.path;
    const bool ok = run_isolated(
        [&] {
          const Case c = make_case(spec_of(*r));
          const Operation op = parse_run_operation(r->op);
          const auto area_polygon = [](const Output& o) {
            Polygon p;
            for (const auto& cyc : o.irreducible) {
              if (cyc.vertices.size() >= 3) p.rings.push_back(cyc.vertices);
            }
            return p;
          };
          const Polygon k = area_polygon(run_operation(c, BooleanOptions{op, r->regular, r->kernel}).output);
          const Polygon e = area_polygon(case_reference(c, op, r->regular, false).output);
          for (const auto& [x, y] : {std::pair{&k, &k}, std::pair{&e, &e}, std::pair{&k, &e}}) {
            if (const auto what = violated_identity(*x, *y)) {
              const Operation show = x == y ? Operation::intersection : Operation::symmetric_difference;
              write_file(target, regression_case_text(*x, *y, show, true,
                                                      {"RationalKernel violates an exact identity: " + *what,
                                                       "found measuring " + r->kernel + " on generator=" + r->generator +
                                                           " variant=" + r->variant + " params=" + r->params +
                                                           " seed=" + std::to_string(r->seed) + " op=" + r->op,
                                                       kKeepAsTest}));
              return;
            }
          }
          _exit(2);  // not reproduced on double polygons
        },
        options.timeout_seconds);
    if (ok && fs::exists(target)) out.push_back(std::move(art));
  }
  std::ofstream list(fs::path(dir) / "artefacts.csv");
  list << "kind,path," << csv_header() << "\n";
  for (const auto& a : out) {
    list << artefact_kind_name(a.kind) << "," << a.path << "," << to_csv(a.row) << "\n";
  }
  return out;
}

std::vector<Artefact> read_artefacts(const std::string& dir) {
  // artefacts.csv, or one per shard (artefacts-shard-i-of-N.csv) before a merge.
  std::vector<fs::path> files;
  if (fs::is_directory(dir)) {
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (name.rfind("artefacts", 0) == 0 && e.path().extension() == ".csv") files.push_back(e.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<Artefact> out;
  for (const auto& f : files) {
    std::ifstream in(f);
    std::string line;
    if (!std::getline(in, line)) continue;  // header
    while (std::getline(in, line)) {
      const auto c1 = line.find(',');
      const auto c2 = line.find(',', c1 + 1);
      if (c1 == std::string::npos || c2 == std::string::npos) continue;
      Artefact a;
      const auto kind = parse_artefact_kind(std::string_view(line).substr(0, c1));
      if (!kind) throw std::runtime_error(f.string() + ": unknown artefact kind '" + line.substr(0, c1) + "'");
      a.kind = *kind;
      a.path = line.substr(c1 + 1, c2 - c1 - 1);
      a.row = parse_csv_row(line.substr(c2 + 1));
      out.push_back(std::move(a));
    }
  }
  return out;
}

}  // namespace mk::experiments
