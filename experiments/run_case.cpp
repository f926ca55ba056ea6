// The runs of one case: the exact reference per (op, regular), then every kernel through
// the public API (operations.hpp: a pair or a set case), each assessed against the
// reference. [MK89 §3.2] [MK89 §3.3]
// Preconditions: see runner.hpp.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <tuple>
#include <sstream>
#include <stdexcept>
#include <typeinfo>

#include "api/mkbool.hpp"
#include "experiments/generators.hpp"
#include "experiments/ogc.hpp"
#include "experiments/operations.hpp"
#include "experiments/peer_verdict.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/runner.hpp"
#include "experiments/verdict.hpp"

#if __has_include("arithmetic/predicates_counters.hpp")
#include "arithmetic/predicates_counters.hpp"
#define MK_EXPERIMENTS_HAVE_COUNTERS 1
#endif

namespace mk::experiments {

namespace {

struct Counts {
  std::optional<std::int64_t> calls;
  std::optional<std::int64_t> fallbacks;
  std::string stages;
};

void reset_counters() {
#ifdef MK_EXPERIMENTS_HAVE_COUNTERS
  PredicateCounters::reset();
#endif
}

// Predicate calls, how many left the first (filter) stage, and how many each stage decided
// (summed over methods and predicates), where the build counts them (CMake option
// MK_COUNTERS); empty otherwise.
Counts read_counters() {
  Counts c;
#ifdef MK_EXPERIMENTS_HAVE_COUNTERS
  const PredicateCounters p = PredicateCounters::read();
  std::int64_t calls = 0, past_filter = 0;
  std::array<std::uint64_t, PredicateCounters::stage_count> by_stage{};
  for (const PredicateMethod m : {PredicateMethod::adaptive, PredicateMethod::interval}) {
    for (const PredicateKind k : {PredicateKind::orient2d, PredicateKind::orient_vectors}) {
      calls += static_cast<std::int64_t>(p.calls(m, k));
      past_filter += static_cast<std::int64_t>(p.past_filter(m, k));
      for (std::size_t s = 0; s < by_stage.size(); ++s) by_stage[s] += p.decided(m, k, static_cast<PredicateStage>(s));
    }
  }
  if (calls > 0) {
    c.calls = calls;
    c.fallbacks = past_filter;
    for (std::size_t s = 0; s < by_stage.size(); ++s) {
      if (by_stage[s] == 0) continue;
      if (!c.stages.empty()) c.stages += ';';
      c.stages += stage_name(static_cast<PredicateStage>(s));
      c.stages += '=';
      c.stages += std::to_string(by_stage[s]);
    }
  }
#endif
  return c;
}

std::string describe(const std::exception& e) {
  if (dynamic_cast<const KernelFailure*>(&e)) return std::string("KernelFailure: ") + e.what();
  if (dynamic_cast<const InvalidInput*>(&e)) return std::string("InvalidInput: ") + e.what();
  return std::string("exception: ") + e.what();
}

// Everything assess() reads from an output, as bytes: equal fingerprints, equal verdicts.
std::string fingerprint(const Output& o) {
  std::string key;
  const auto put = [&](const void* p, std::size_t n) { key.append(static_cast<const char*>(p), n); };
  put(&o.unbounded, sizeof o.unbounded);
  for (const auto& c : o.irreducible) {
    const std::size_t n = c.vertices.size();
    put(&c.type, sizeof c.type);
    put(&n, sizeof n);
    put(c.vertices.data(), n * sizeof(Point));
    for (const auto& e : c.exact) key += e + ',';
  }
  return key;
}

ResultRow base_row(const IndexedCase& c, std::size_t size, Operation op, bool regular) {
  ResultRow r;
  r.case_index = c.index;
  r.generator = c.spec.generator;
  r.variant = c.spec.variant;
  r.params = c.spec.params_text();
  r.seed = c.spec.seed;
  r.size = size;
  r.op = run_operation_name(c.spec, op);
  r.regular = regular;
  return r;
}

std::size_t count_vertices(const MultiPolygon& mp) {
  std::size_t n = 0;
  for (const auto& p : mp) {
    n += p.shell.size();
    for (const auto& h : p.holes) n += h.size();
  }
  return n;
}

// One peer's run: the library's operation, timed, and its verdict against the reference
// (null when mkbool refused the input).
void run_peer_into(ResultRow& r, const std::string& peer, const Case& cs, const std::optional<MultiPolygon>& a_ogc,
                   const std::optional<MultiPolygon>& b_ogc, Operation op, const ExactResult* ref) {
  const PeerInput a{&cs.a, a_ogc ? &*a_ogc : nullptr}, b{&cs.b, b_ogc ? &*b_ogc : nullptr};
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const PeerOutput out = run_peer(peer, a, b, op);
    r.op_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
    r.vertices_out = static_cast<std::int64_t>(count_vertices(out.polygons));
    const PeerAssessment pa = assess_peer(out, ref, input_resolution(cs.a, cs.b));
    r.verdict = pa.assessment.verdict;
    r.symdiff_area = pa.assessment.symdiff_area;
    r.area_error = pa.assessment.area_error;
    r.message = pa.assessment.note;
    r.rounding_bound = pa.bound;
    r.geos_valid = pa.geos_valid;
    r.exact_valid = pa.exact_valid;
    if (out.is_exact && ref != nullptr && r.verdict == Verdict::wrong) {
      // An exact library disagrees with the exact reference: an independent point check
      // says which of the two is wrong (the reference's bugs are the ones that matter).
      const PointCheck check = independent_point_check(cs.a, cs.b, op, *ref, peer_cycles(out), out.unbounded);
      const std::string who = check.wrong == "other" ? peer + " wrong" : check.wrong == "mkbool" ? "MKBOOL WRONG" : "undecided";
      r.message += (r.message.empty() ? "" : "; ") + std::string("independent point check: ") + who +
                   (check.explanation.empty() ? "" : " (" + check.explanation + ")");
    }
  } catch (const PeerUnsupported& e) {
    r.verdict = Verdict::unsupported;
    r.message = e.what();
  } catch (const std::exception& e) {
    r.verdict = Verdict::exception;
    r.message = e.what();
  } catch (...) {
    r.verdict = Verdict::exception;
    r.message = "unknown exception";
  }
}

bool runs_peers(const IndexedCase& c, std::size_t size, const RunOptions& o) {
  if (is_external_generator(c.spec.generator)) return true;
  return c.index % std::max<std::size_t>(1, o.peer_every) == 0 && (o.peer_max_size == 0 || size <= o.peer_max_size);
}

}  // namespace

Shard parse_shard(const std::string& text) {
  Shard s;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> s.index >> slash >> s.count) || slash != '/' || s.count == 0 || s.index >= s.count || !in.eof()) {
    throw std::invalid_argument("shard must be i/N with 0 <= i < N, got '" + text + "'");
  }
  return s;
}

std::vector<IndexedCase> select_shard(const std::vector<CaseSpec>& plan, Shard shard) {
  std::vector<IndexedCase> out;
  for (std::size_t i = shard.index; i < plan.size(); i += shard.count) out.push_back({i, plan[i]});
  return out;
}

std::size_t slot_count(const RunOptions& o) { return o.ops.size() * o.regular.size() * (1 + o.kernels.size()); }

void run_case(const IndexedCase& c, const RunOptions& o, std::size_t first_slot,
              const std::function<void(std::size_t)>& on_start, const std::function<void(const ResultRow&)>& on_row,
              const std::function<void(std::size_t)>& on_generated) {
  Case cs;
  try {
    cs = make_case(c.spec);
  } catch (const std::exception& e) {
    // A generator that cannot build its case: one row, no runs.
    ResultRow r = base_row(c, 0, o.ops.front(), o.regular.front());
    r.kernel = "reference";
    r.verdict = Verdict::invalid_input;
    r.message = "generator: " + std::string(e.what());
    on_row(r);
    return;
  }
  if (on_generated) on_generated(cs.size());
  run_built_case(c, cs, o, first_slot, on_start, on_row);
}

void run_built_case(const IndexedCase& c, const Case& cs, const RunOptions& o, std::size_t first_slot,
                    const std::function<void(std::size_t)>& on_start,
                    const std::function<void(const ResultRow&)>& on_row) {
  const std::size_t per_group = 1 + o.kernels.size();
  const bool paper_variants = cs.size() <= o.paper_reference_limit;
  const bool external = is_external_generator(c.spec.generator);
  // Fill-rule and set cases (generators_fill.cpp, generators_set.cpp): no peers (their
  // adapters read the rings as OGC polygons, not by a fill rule, and run binary operations).
  const bool with_peers = !fill_rule_of(c.spec) && runs_peers(c, cs.size(), o) &&
                          std::any_of(o.kernels.begin(), o.kernels.end(), [](const std::string& k) { return is_peer(k); });
  std::optional<MultiPolygon> a_ogc = cs.a_ogc, b_ogc = cs.b_ogc;
  if (with_peers && !external) {
    a_ogc = ogc_form(cs.a);
    b_ogc = ogc_form(cs.b);
  }
  for (std::size_t g = first_slot / per_group; g < o.ops.size() * o.regular.size(); ++g) {
    const Operation op = o.ops[g / o.regular.size()];
    const bool regular = o.regular[g % o.regular.size()];
    const std::size_t base = g * per_group;
    const std::size_t first_kernel = first_slot > base ? first_slot - base - 1 : 0;
    if (!runs_operation(c.spec, op)) continue;  // set cases: union and intersection only
    // The reference (recomputed when a run after it in this group crashed or timed out).
    on_start(base);
    ExactResult ref;
    try {
      ref = case_reference(cs, op, regular, paper_variants);
    } catch (const std::exception& e) {
      ResultRow r = base_row(c, cs.size(), op, regular);
      r.kernel = "reference";
      const bool refused = dynamic_cast<const InvalidInput*>(&e) != nullptr;
      r.verdict = refused ? (external ? Verdict::refused : Verdict::invalid_input) : Verdict::error;
      r.message = describe(e);
      on_row(r);
      if (!(refused && external)) continue;
      // An external input outside mkbool's domain: every kernel refuses it (the same check
      // runs first in each), and the peers still run, judged by validity alone.
      for (std::size_t k = first_kernel; k < o.kernels.size(); ++k) {
        if (is_peer(o.kernels[k]) && (!regular || !with_peers)) continue;
        on_start(base + 1 + k);
        ResultRow row = base_row(c, cs.size(), op, regular);
        row.kernel = o.kernels[k];
        if (is_peer(o.kernels[k])) {
          run_peer_into(row, o.kernels[k], cs, a_ogc, b_ogc, op, nullptr);
        } else {
          row.verdict = Verdict::refused;
          row.message = r.message;
        }
        on_row(row);
      }
      continue;
    }
    std::map<std::string, Assessment> assessed;  // by output fingerprint, in this group
    // GEOS's isValid of exact kernels' written polygons and its reason, by fingerprint.
    std::map<std::string, std::pair<std::optional<bool>, std::string>> geos_checked;
    const std::optional<double> exact_area =
        ref.unbounded ? std::nullopt : std::optional<double>(RationalKernel::to_nearest(ref.area));
    for (std::size_t k = first_kernel; k < o.kernels.size(); ++k) {
      if (is_peer(o.kernels[k]) && (!regular || !with_peers)) continue;  // peers: regular operations only
      on_start(base + 1 + k);
      ResultRow r = base_row(c, cs.size(), op, regular);
      r.kernel = o.kernels[k];
      r.exact_area = exact_area;
      if (o.fault_injection) o.fault_injection(o.kernels[k], c.spec);
      if (is_peer(o.kernels[k])) {
        run_peer_into(r, o.kernels[k], cs, a_ogc, b_ogc, op, &ref);
        on_row(r);
        continue;
      }
      try {
        reset_counters();
        BooleanOptions options{op, regular, o.kernels[k]};
        options.area = false;  // the verdict measures areas against the reference itself
        options.exact_coordinates = true;  // assess() compares exact results exactly
        options.rounding = o.rounding;
        options.grid = o.grid;
        const BooleanOutput out = run_operation(cs, options);  // with the case's fill rule
        const Counts counts = read_counters();
        r.predicate_calls = counts.calls;
        r.predicate_fallbacks = counts.fallbacks;
        r.predicate_stages = counts.stages;
        r.op_ns = out.stats.op_ns;
        r.vertices_in = static_cast<std::int64_t>(out.stats.vertices_in);
        r.crossings = static_cast<std::int64_t>(out.stats.crossings);
        r.vertices_out = static_cast<std::int64_t>(out.stats.vertices_out);
        if (!out.output.unbounded) {
          r.nearest_valid = out.output.rounded_valid;
          r.certified_snapped = out.output.rounding.snapped;
          r.certified_valid = out.output.rounding.valid;
          r.snap_displacement = out.output.rounding.max_displacement;
        }
        // Kernels that decide alike often output the same result: assess it once.
        const std::string key = fingerprint(out.output);
        auto cached = assessed.find(key);
        if (cached == assessed.end()) cached = assessed.emplace(key, assess(out.output, ref)).first;
        const Assessment& a = cached->second;
        r.verdict = a.verdict;
        r.symdiff_area = a.symdiff_area;
        r.area_error = a.area_error;
        r.message = a.note;
        if (a.verdict == Verdict::valid_different || a.verdict == Verdict::invalid_output) {
          r.rounding_bound = rounding_bound(input_resolution(cs.a, cs.b), perimeter(ref.cycles),
                                            perimeter(exact_cycles(out.output)));
        }
        // Issue 12: the output as written (certified rounding) is valid for GEOS too (asked
        // about its copy scaled exactly into GEOS's range; not asked when that copy would
        // spread too far, see geos_is_valid).
        if (is_exact_kernel(o.kernels[k]) && !out.output.unbounded) {
          auto geos = geos_checked.find(key);
          if (geos == geos_checked.end()) {
            std::string why;
            const std::optional<bool> valid = geos_is_valid(out.output.polygons, &why);
            geos = geos_checked.emplace(key, std::pair{valid, why}).first;
          }
          r.geos_valid = geos->second.first;
          if (r.geos_valid == false) {
            r.message += (r.message.empty() ? "" : "; ") + std::string("GEOS isValid of the written output: ") +
                         geos->second.second;
          }
        }
      } catch (const std::exception& e) {
        r.verdict = Verdict::error;
        r.message = describe(e);
      } catch (...) {
        r.verdict = Verdict::error;
        r.message = "unknown exception";
      }
      on_row(r);
    }
  }
}

void fill_oracle_agreement(std::vector<ResultRow>& rows) {
  std::map<std::tuple<std::uint64_t, std::string, bool>, const ResultRow*> oracle;
  for (const auto& r : rows) {
    if (r.kernel == "cgal_epeck") oracle[{r.case_index, r.op, r.regular}] = &r;
  }
  for (auto& r : rows) {
    if (r.kernel == "reference" || is_peer(r.kernel) || !is_exact_kernel(r.kernel)) continue;
    const auto it = oracle.find({r.case_index, r.op, r.regular});
    if (it == oracle.end()) continue;
    const ResultRow& cgal = *it->second;
    if (cgal.verdict == Verdict::exact_area) {
      r.oracle_agrees = r.verdict == Verdict::exact_match;
    } else if (cgal.verdict == Verdict::wrong || cgal.verdict == Verdict::invalid_output) {
      r.oracle_agrees = false;
      const auto at = cgal.message.find("independent point check: ");
      r.message += std::string(r.message.empty() ? "" : "; ") + "oracle: CGAL Epeck disagrees" +
                   (at == std::string::npos ? std::string() : "; " + cgal.message.substr(at));
    } else {
      r.message += std::string(r.message.empty() ? "" : "; ") + "oracle: CGAL Epeck gave no result (" +
                   std::string(verdict_name(cgal.verdict)) + ")";
    }
  }
}

}  // namespace mk::experiments
