// The experiment harness from Python: the generators and the plan of a sweep, sweeps of
// the built-in generators (forked workers, as mkbool-experiment runs them), and runs of
// cases built in Python (a generator written there) in C++ threads, as rows.
// [MK89 §3.3] (inexact arithmetic may fail; the failures are the data) [BRIEF §5]
// Preconditions: the GIL is held on entry; run_sweep forks workers that run C++ only.
#include <algorithm>
#include <atomic>
#include <thread>

#include "experiments/generators.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/results.hpp"
#include "experiments/runner.hpp"
#include "module.hpp"

namespace mk::python {

namespace {

using namespace mk::experiments;

py::object opt(const std::optional<double>& v) { return v ? py::object(py::float_(*v)) : py::object(py::none()); }
py::object opt(const std::optional<std::int64_t>& v) { return v ? py::object(py::int_(*v)) : py::object(py::none()); }
py::object opt(const std::optional<bool>& v) { return v ? py::object(py::bool_(*v)) : py::object(py::none()); }

// One row as a dict whose keys are the CSV schema's columns (experiments/README.md).
py::dict row_dict(const ResultRow& r) {
  py::dict d;
  d["case"] = r.case_index;
  d["generator"] = r.generator;
  d["variant"] = r.variant;
  d["params"] = r.params;
  d["seed"] = r.seed;
  d["size"] = r.size;
  d["op"] = r.op;
  d["regular"] = r.regular;
  d["kernel"] = r.kernel;
  d["verdict"] = std::string(verdict_name(r.verdict));
  d["area_error"] = opt(r.area_error);
  d["symdiff_area"] = opt(r.symdiff_area);
  d["exact_area"] = opt(r.exact_area);
  d["op_ns"] = opt(r.op_ns);
  d["predicate_calls"] = opt(r.predicate_calls);
  d["predicate_fallbacks"] = opt(r.predicate_fallbacks);
  d["predicate_stages"] = r.predicate_stages;
  d["vertices_in"] = opt(r.vertices_in);
  d["crossings"] = opt(r.crossings);
  d["vertices_out"] = opt(r.vertices_out);
  d["message"] = r.message;
  d["rounding_bound"] = opt(r.rounding_bound);
  d["oracle_agrees"] = opt(r.oracle_agrees);
  d["geos_valid"] = opt(r.geos_valid);
  d["exact_valid"] = opt(r.exact_valid);
  d["nearest_valid"] = opt(r.nearest_valid);
  d["certified_snapped"] = opt(r.certified_snapped);
  d["certified_valid"] = opt(r.certified_valid);
  d["snap_displacement"] = opt(r.snap_displacement);
  return d;
}

py::list row_list(const std::vector<ResultRow>& rows) {
  py::list out;
  for (const auto& r : rows) out.append(row_dict(r));
  return out;
}

SweepLevel level_named(const std::string& name) {
  if (name == "quick") return SweepLevel::quick;
  if (name == "normal" || name == "default") return SweepLevel::normal;
  if (name == "full") return SweepLevel::full;
  throw std::invalid_argument("unknown sweep level '" + name + "' (quick, normal or full)");
}

// Back ends by name, as `mkbool-experiment run --kernels` checks them.
RunOptions run_options(const std::vector<std::string>& backends, const std::vector<std::string>& ops,
                       const std::vector<bool>& regular, int jobs) {
  RunOptions o;
  for (const auto& k : backends) {
    const auto kernels = kernel_names();
    const auto peers = peer_names();
    const bool known = std::find(kernels.begin(), kernels.end(), k) != kernels.end() ||
                       std::find(peers.begin(), peers.end(), k) != peers.end();
    if (!known) {
      std::string names;
      for (const auto n : kernels) names += (names.empty() ? "" : ", ") + std::string(n);
      for (const auto n : peers) names += ", " + std::string(n);
      throw std::invalid_argument("back end '" + k + "' is not built into this module (built: " + names + ")");
    }
    o.kernels.push_back(k);
  }
  o.ops.clear();
  for (const auto& op : ops) o.ops.push_back(operation_named(op));
  if (o.ops.empty()) throw std::invalid_argument("no operation to run");
  o.regular = regular;
  if (o.regular.empty()) throw std::invalid_argument("no regularity to run (regular=[True, False] runs both)");
  o.jobs = std::max(1, jobs);
  return o;
}

CaseSpec spec_from(const py::dict& d) {
  CaseSpec s;
  s.generator = d["generator"].cast<std::string>();
  s.variant = d.contains("variant") ? d["variant"].cast<std::string>() : "";
  s.params = parse_params(d.contains("params") ? d["params"].cast<std::string>() : "");
  s.seed = d["seed"].cast<std::uint64_t>();
  return s;
}

py::dict spec_dict(std::uint64_t index, const CaseSpec& s) {
  py::dict d;
  d["index"] = index;
  d["generator"] = s.generator;
  d["variant"] = s.variant;
  d["params"] = s.params_text();
  d["seed"] = s.seed;
  return d;
}

}  // namespace

void bind_harness(py::module_& m) {
  auto h = m.def_submodule("harness", "The experiment harness (experiments/): generators, sweeps, verdicts.");

  h.def("generators", [] {
    py::list out;
    for (const auto& g : experiments::generators()) {
      py::dict d;
      d["name"] = std::string(g.name);
      d["stresses"] = std::string(g.stresses);
      py::list variants;
      for (const auto v : g.variants) variants.append(std::string(v));
      d["variants"] = variants;
      out.append(d);
    }
    return out;
  });
  h.def("peer_names", [] {
    py::list out;
    for (const auto p : peer_names()) out.append(std::string(p));
    return out;
  });
  h.def("csv_columns", [] {
    py::list out;
    for (const auto c : csv_columns()) out.append(std::string(c));
    return out;
  });
  h.def("verdict_names", [] {
    py::list out;
    for (const Verdict v : all_verdicts) out.append(std::string(verdict_name(v)));
    for (const Verdict v : peer_verdicts) {
      const std::string name(verdict_name(v));
      if (!out.contains(name)) out.append(name);
    }
    return out;
  });
  h.def("mix_seed", [](std::uint64_t base, const std::string& generator, std::uint64_t index) {
    return mix_seed(base, generator, index);
  });
  h.def(
      "plan",
      [](const std::vector<std::string>& generators, const std::string& level, int seeds, std::uint64_t base_seed) {
        PlanOptions po;
        po.level = level_named(level);
        po.seeds = seeds;
        po.base_seed = base_seed;
        po.generators = generators;
        for (const auto& g : generators) find_generator(g);  // unknown names: std::invalid_argument
        py::list out;
        const auto plan = plan_sweep(po);
        for (std::size_t i = 0; i < plan.size(); ++i) out.append(spec_dict(i, plan[i]));
        return out;
      },
      py::arg("generators"), py::arg("level") = "quick", py::arg("seeds") = 0, py::arg("base_seed") = 1);
  h.def("make_case", [](const py::dict& spec) {
    const Case c = make_case(spec_from(spec));
    return py::make_tuple(InputPolygon(std::make_shared<const Polygon>(c.a)),
                          InputPolygon(std::make_shared<const Polygon>(c.b)));
  });
  // Built-in generators' cases (specs from plan), in forked workers with a time limit per
  // run, as mkbool-experiment runs them; or in this process when isolate is false.
  h.def(
      "run_specs",
      [](const std::vector<py::dict>& specs, const std::vector<std::string>& backends, const std::vector<std::string>& ops,
         const std::vector<bool>& regular, int jobs, bool isolate, double timeout, std::size_t peer_every) {
        RunOptions o = run_options(backends, ops, regular, jobs);
        o.isolate = isolate;
        o.timeout_seconds = timeout;
        o.peer_every = std::max<std::size_t>(1, peer_every);
        std::vector<IndexedCase> cases;
        for (const auto& d : specs) cases.push_back({d["index"].cast<std::uint64_t>(), spec_from(d)});
        for (const auto& c : cases) find_generator(c.spec.generator);
        std::vector<ResultRow> rows;
        {
          py::gil_scoped_release release;
          rows = run_sweep(cases, o, "", nullptr);
        }
        return row_list(rows);
      },
      py::arg("specs"), py::arg("backends"), py::arg("ops"), py::arg("regular"), py::arg("jobs") = 1,
      py::arg("isolate") = true, py::arg("timeout") = 60.0, py::arg("peer_every") = 1);
  // Cases built in Python: (index, generator, variant, params, seed, A, B) each, run in C++
  // threads in this process (the GIL released), rows sorted by case and run.
  h.def(
      "run_built",
      [](const std::vector<py::tuple>& built, const std::vector<std::string>& backends, const std::vector<std::string>& ops,
         const std::vector<bool>& regular, int jobs) {
        const RunOptions o = run_options(backends, ops, regular, jobs);
        struct Item {
          IndexedCase c;
          Case cs;
        };
        std::vector<Item> items;
        for (const auto& t : built) {
          Item it;
          it.c.index = t[0].cast<std::uint64_t>();
          it.c.spec.generator = t[1].cast<std::string>();
          it.c.spec.variant = t[2].cast<std::string>();
          it.c.spec.params = parse_params(t[3].cast<std::string>());
          it.c.spec.seed = t[4].cast<std::uint64_t>();
          it.cs.spec = it.c.spec;
          it.cs.a = *t[5].cast<InputPolygon>().polygon;
          it.cs.b = *t[6].cast<InputPolygon>().polygon;
          items.push_back(std::move(it));
        }
        std::vector<std::vector<ResultRow>> per_case(items.size());
        {
          py::gil_scoped_release release;
          std::atomic<std::size_t> next{0};
          const auto work = [&] {
            for (std::size_t i = next++; i < items.size(); i = next++) {
              run_built_case(items[i].c, items[i].cs, o, 0, [](std::size_t) {},
                             [&](const ResultRow& r) { per_case[i].push_back(r); });
            }
          };
          std::vector<std::thread> pool;
          const int workers = std::min<int>(o.jobs, static_cast<int>(std::max<std::size_t>(1, items.size())));
          for (int t = 1; t < workers; ++t) pool.emplace_back(work);
          work();
          for (auto& t : pool) t.join();
        }
        std::vector<ResultRow> rows;
        for (auto& v : per_case) rows.insert(rows.end(), v.begin(), v.end());
        fill_oracle_agreement(rows);
        return row_list(rows);
      },
      py::arg("built"), py::arg("backends"), py::arg("ops"), py::arg("regular"), py::arg("jobs") = 1);
}

}  // namespace mk::python
