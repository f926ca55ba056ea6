// The --stats line and the exact validity check of rounded output. [MK89 §3.3] [Sh97 §4.2]
// Preconditions: `result` comes from mk::compute.
#include "cli/stats.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <vector>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/boolean_op.hpp"  // before to_output.hpp: step6_construct.hpp needs EfEntry declared
#include "core/to_output.hpp"

namespace mk::cli {

namespace {

// Per method and predicate: the calls, and how many of them each stage decided (the
// method's stages in order, stages that decided nothing left out).
nlohmann::ordered_json counters_json(const PredicateCounters& c) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const PredicateMethod m : {PredicateMethod::adaptive, PredicateMethod::interval}) {
    for (const PredicateKind k : {PredicateKind::orient2d, PredicateKind::orient_vectors}) {
      if (c.calls(m, k) == 0) continue;
      nlohmann::ordered_json decided = nlohmann::ordered_json::object();
      const auto add = [&](const auto& stages) {
        for (const PredicateStage s : stages) {
          if (const auto n = c.decided(m, k, s); n > 0) decided[std::string(stage_name(s))] = n;
        }
      };
      if (m == PredicateMethod::adaptive) {
        add(adaptive_stages);
      } else {
        add(interval_stages);
      }
      out[std::string(method_name(m))][std::string(kind_name(k))] = {{"calls", c.calls(m, k)}, {"decided", decided}};
    }
  }
  return out;
}

}  // namespace

bool is_output_valid(const Output& output) {
  if (output.rounding.snapped) return output.rounding.valid;  // checked exactly after snapping
  if (output.rounded_valid) return *output.rounded_valid;
  std::vector<std::vector<Point>> rings;
  rings.reserve(output.irreducible.size());
  for (const auto& c : output.irreducible) rings.push_back(c.vertices);
  return is_valid_rounded_output<ExactKernel>(rings);
}

std::string stats_json(const BooleanOutput& result, const PredicateCounters& counters) {
  const BooleanStats& s = result.stats;
  nlohmann::ordered_json j;
  j["kernel"] = s.kernel;
  j["op_ns"] = s.op_ns;
  j["vertices_in"] = s.vertices_in;
  j["crossings"] = s.crossings;
  j["vertices_out"] = s.vertices_out;
  j["rounded_valid"] = result.output.rounded_valid ? nlohmann::ordered_json(*result.output.rounded_valid) : nullptr;
  // JSON has no infinity: an area beyond the largest double is null, with the flag saying
  // why (null alone means unbounded or not computed).
  j["area"] = s.area && std::isfinite(*s.area) ? nlohmann::ordered_json(*s.area) : nullptr;
  j["area_beyond_double"] = s.area_beyond_double;
  j["area_exact"] = s.area_exact ? nlohmann::ordered_json(*s.area_exact) : nullptr;
  const RoundingReport& r = result.output.rounding;
  nlohmann::ordered_json rounding;
  rounding["mode"] = r.mode == RoundingMode::certified ? "certified" : "nearest";
  rounding["snapped"] = r.snapped;
  rounding["grid"] = r.snapped ? nlohmann::ordered_json(r.grid) : nullptr;
  rounding["user_grid"] = r.user_grid;
  rounding["regridded"] = r.regridded;
  rounding["max_displacement"] = r.max_displacement ? nlohmann::ordered_json(*r.max_displacement) : nullptr;
  rounding["hot_pixels"] = r.hot_pixels;
  rounding["incidences"] = r.incidences;
  rounding["valid"] = r.valid;
  j["rounding"] = rounding;
  if constexpr (PredicateCounters::enabled) j["predicates"] = counters_json(counters);
  return j.dump();
}

}  // namespace mk::cli
