// The experiment generators, one named function each, and the registry that plans a sweep
// from them. Each name is also the name of the degeneracy it stresses (comments in core/
// use the same words), and each failing case it produces becomes
// tests/regression/cases/<generator>_<seed>.wkt.
// [MK89 §2.2] (vertex-complete polygons) [MK89 Appendix A] (figures 6-12) [KMPSY08]
// Preconditions: a spec's variant is one the generator lists; otherwise std::invalid_argument.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "core/fill_rule.hpp"
#include "experiments/case.hpp"

namespace mk::experiments {

// Degenerate configurations on the integer lattice (generators_degenerate.cpp).
PolygonPair shared_vertex(const CaseSpec& spec);
PolygonPair shared_edge(const CaseSpec& spec);
PolygonPair collinear_overlap(const CaseSpec& spec);
PolygonPair vertex_on_edge(const CaseSpec& spec);
PolygonPair identical(const CaseSpec& spec);
PolygonPair same_vertex_set(const CaseSpec& spec);
PolygonPair hole_filled(const CaseSpec& spec);
PolygonPair holes_collinear(const CaseSpec& spec);
PolygonPair nested_touching(const CaseSpec& spec);
PolygonPair collinear_vertices(const CaseSpec& spec);
// Random polygons (generators_random.cpp).
PolygonPair grid_random(const CaseSpec& spec);
PolygonPair blob(const CaseSpec& spec);
PolygonPair star(const CaseSpec& spec);
// Near-degenerate doubles (generators_numeric.cpp).
PolygonPair rotated(const CaseSpec& spec);
PolygonPair magnitude(const CaseSpec& spec);
PolygonPair ulp_perturbed(const CaseSpec& spec);
PolygonPair kettner_grid(const CaseSpec& spec);
// The paper's example figures (generators_paper.cpp).
PolygonPair paper_figures(const CaseSpec& spec);
// Self-crossing and multi-part input read by a fill rule (generators_fill.cpp), run only when
// named (`run --generators ...`), never in the default sweep.
PolygonPair self_crossing_random(const CaseSpec& spec);
PolygonPair bowtie_degenerate(const CaseSpec& spec);
PolygonPair pentagram(const CaseSpec& spec);
PolygonPair traced_twice(const CaseSpec& spec);
PolygonPair overlapping_multipart(const CaseSpec& spec);
bool is_fill_generator(std::string_view name);
// Sets of polygons for the N-ary operations (generators_set.cpp): a set case's parts run
// through union_all and intersection_all instead of A op B (operations.hpp).
MultiPolygon random_set(const CaseSpec& spec);
MultiPolygon coverage_grid(const CaseSpec& spec);
MultiPolygon nested_parts(const CaseSpec& spec);
bool is_set_generator(std::string_view name);
// The fill rule a case's runs use: the parameter rule = 0-4 (evenodd, nonzero, positive,
// negative, union) of a fill generator's case (default 0, evenodd) or a set generator's
// (default 4, union), none for other generators. Throws std::invalid_argument for another value.
std::optional<FillRule> fill_rule_of(const CaseSpec& spec);

enum class SweepLevel { quick, normal, full };

struct Generator {
  std::string_view name;
  std::string_view stresses;  // one line for the report and --list
  std::vector<std::string_view> variants;
  PolygonPair (*make)(const CaseSpec&);
  MultiPolygon (*make_set)(const CaseSpec&) = nullptr;  // set generators instead of make
};

const std::vector<Generator>& generators();
const Generator& find_generator(std::string_view name);  // throws std::invalid_argument

// Generates a case from its spec (a set case: Case::parts, see case.hpp).
Case make_case(const CaseSpec& spec);

// Generators whose cases come from outside (reported, cases): their inputs may lie outside
// mkbool's domain, which is then a `refused` verdict, not a generator bug.
bool is_external_generator(std::string_view name);

struct PlanOptions {
  SweepLevel level = SweepLevel::normal;
  int seeds = 0;  // random instances per configuration; 0: the level's default
  std::uint64_t base_seed = 1;
  std::vector<std::string> generators;  // empty: all
};

// Every case of a sweep, in a fixed order (shards take every N-th).
std::vector<CaseSpec> plan_sweep(const PlanOptions& options);

}  // namespace mk::experiments
