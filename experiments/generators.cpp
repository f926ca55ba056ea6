// The generator registry, case specs and the sweep plans (which cases each sweep level
// runs). [MK89 Appendix A] [KMPSY08 §4]
// Preconditions: none.
#include "experiments/generators.hpp"

#include <array>
#include <charconv>

#include <stdexcept>

#include "api/mkbool.hpp"
#include "experiments/external_cases.hpp"

namespace mk::experiments {

std::int64_t CaseSpec::param(std::string_view name, std::int64_t fallback) const {
  for (const auto& [k, v] : params) {
    if (k == name) return v;
  }
  return fallback;
}

std::string CaseSpec::params_text() const {
  std::string out;
  for (const auto& [k, v] : params) {
    if (!out.empty()) out += ';';
    out += k;
    out += '=';
    out += std::to_string(v);
  }
  return out;
}

std::string CaseSpec::stem() const {
  std::string out = generator;
  out += '_';
  out += std::to_string(seed);
  if (!variant.empty()) {
    out += '_';
    out += variant;
  }
  for (const auto& [k, v] : params) {
    out += '_';
    out += k;
    out += v < 0 ? 'm' + std::to_string(-v) : std::to_string(v);
  }
  return out;
}

std::vector<std::pair<std::string, std::int64_t>> parse_params(std::string_view text) {
  std::vector<std::pair<std::string, std::int64_t>> out;
  while (!text.empty()) {
    const auto end = text.find(';');
    const std::string_view item = text.substr(0, end);
    const auto eq = item.find('=');
    std::int64_t value = 0;
    if (eq == std::string_view::npos ||
        std::from_chars(item.data() + eq + 1, item.data() + item.size(), value).ec != std::errc()) {
      throw std::invalid_argument("bad parameter '" + std::string(item) + "' (expected name=integer)");
    }
    out.emplace_back(std::string(item.substr(0, eq)), value);
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return out;
}

std::size_t Case::size() const {
  std::size_t n = 0;
  for (const auto* p : {&a, &b}) {
    for (const auto& r : p->rings) n += r.size();
  }
  return n;
}

std::uint64_t mix_seed(std::uint64_t base, std::string_view generator, std::uint64_t index) {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a of the name
  for (const char c : generator) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  std::uint64_t z = base ^ h ^ (index * 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;  // SplitMix64 finaliser
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return (z ^ (z >> 31)) >> 1;  // 63 bits: seeds print and parse as signed integers too
}

const std::vector<Generator>& generators() {
  static const std::vector<Generator> all{
      {"shared_vertex", "A and B share a vertex (outside, rotated about it)", {"outside", "rotated90", "star_rotated90"}, &shared_vertex},
      {"shared_edge", "A and B share a whole edge", {"opposite_side", "same_side", "star_reflected"}, &shared_edge},
      {"collinear_overlap", "edges overlap partly on one line, same or opposite direction", {"same", "opposite"}, &collinear_overlap},
      {"vertex_on_edge", "a vertex of B lies inside an edge of A", {"outside", "inside", "crossing"}, &vertex_on_edge},
      {"identical", "B is A again: shifted start, reversed, with a hole", {"same", "shifted_start", "reversed", "with_hole_reversed"}, &identical},
      {"same_vertex_set", "the same vertices in another order [MK89 Fig. 7]", {"two_centres"}, &same_vertex_set},
      {"hole_filled", "B fills A's hole (exactly, reversed, larger); holes touching the outer ring; hole-type A", {"exact_fill", "reversed_fill", "larger_fill", "hole_type", "touching_vertex", "touching_twice", "touching_twice_overlap"}, &hole_filled},
      {"holes_collinear", "holes of A and B with edges on common lines", {"adjacent_holes", "overlapping_holes", "hole_on_boundary"}, &holes_collinear},
      {"nested_touching", "B inside A touching at a vertex, along an edge; hole-type B", {"vertex", "edge", "vertex_on_edge", "strictly_inside", "hole_type"}, &nested_touching},
      {"collinear_vertices", "redundant vertices in the middle of edges", {"same_region", "overlap"}, &collinear_vertices},
      {"grid_random", "random stars on a small integer grid (dense coincidences)", {"simple", "holes", "hole_type"}, &grid_random},
      {"paper_figures", "analogues of the paper's figures 6-12", {"fig6_two_stars", "fig7_same_vertex_set", "fig8_three_parts", "fig9_three_holes", "fig10_collinear_point", "fig11_touching_edge", "fig12_touching_parts"}, &paper_figures},
      {"rotated", "a lattice degeneracy rotated by a random angle (collinearity broken by rounding)",
       {"shared_vertex", "shared_edge", "collinear_overlap", "vertex_on_edge", "identical", "same_vertex_set", "hole_filled",
        "holes_collinear", "nested_touching", "collinear_vertices", "paper_figures"},
       &rotated},
      {"magnitude", "a lattice configuration at 10^e, e in -300..300 (param e): products of coordinates underflow or overflow",
       {"shared_vertex", "shared_edge", "collinear_overlap", "vertex_on_edge", "identical", "same_vertex_set", "hole_filled",
        "holes_collinear", "nested_touching", "collinear_vertices", "paper_figures"},
       &magnitude},
      {"ulp_perturbed", "B's vertex k ulps off A's slanted edge, k in -8..8", {"outside_triangle", "crossing_triangle"}, &ulp_perturbed},
      {"kettner_grid", "Kettner et al.'s orient2d grids as polygon pairs (p + (i, j) ulps)", {"shared_edge_a", "shared_edge_b", "chain_a"}, &kettner_grid},
      {"blob", "two smooth curves of n vertices crossing twice", {"smooth"}, &blob},
      {"star", "two random star polygons of n vertices, about n^2/400 crossings", {"random"}, &star},
      {"self_crossing_random", "random lattice rings crossing themselves and each other, a hole sometimes (fill rule: param rule)", {"lattice", "rotated"}, &self_crossing_random},
      {"bowtie_degenerate", "bow-ties sharing vertices and crossing points (fill rule: param rule)", {"lattice", "rotated"}, &bowtie_degenerate},
      {"pentagram", "star polygons {5/2} and 7-point stars, centres wound 2-3 times (fill rule: param rule)", {"lattice", "rotated"}, &pentagram},
      {"traced_twice", "a ring traced twice, with the same ring again or reversed (fill rule: param rule)", {"lattice", "rotated"}, &traced_twice},
      {"overlapping_multipart", "overlapping parts with holes sharing edges and vertices (fill rule: param rule)", {"lattice", "rotated"}, &overlapping_multipart},
      {"random_set", "n random lattice polygons (rectangles, triangles, convex, some with holes, some repeated) overlapping and sharing edges and vertices (set: union_all, intersection_all)", {"lattice", "rotated"}, nullptr, &random_set},
      {"coverage_grid", "an n x n grid of unit squares sharing every edge, some missing, split or merged (T-junctions) (set)", {"lattice", "rotated"}, nullptr, &coverage_grid},
      {"nested_parts", "squares with holes holding parts that fill them, touch them or nest again, and parts around whole nests (set)", {"lattice", "rotated"}, nullptr, &nested_parts},
      {"reported", "inputs of public issue reports of polygon Boolean libraries (experiments/reported/*.jsonl; variant = case id)", {}, &reported},
      {"cases", "the user's own pairs (run --cases FILE.jsonl; variant = case id)", {}, &cases},
  };
  return all;
}

const Generator& find_generator(std::string_view name) {
  for (const auto& g : generators()) {
    if (g.name == name) return g;
  }
  // Not the whole list: with the fill generators it no longer fits one short line.
  throw std::invalid_argument("unknown generator '" + std::string(name) + "' (`mkbool-experiment list` names all " +
                              std::to_string(generators().size()) + ")");
}

bool is_external_generator(std::string_view name) { return name == "reported" || name == "cases"; }

Case make_case(const CaseSpec& spec) {
  if (is_external_generator(spec.generator)) return make_external_case(spec);
  const Generator& g = find_generator(spec.generator);
  if (g.make_set != nullptr) {
    Case c{spec, {}, {}, std::nullopt, std::nullopt};
    c.parts = g.make_set(spec);
    c.a = fill_rule_polygon(*c.parts, *fill_rule_of(spec));
    return c;
  }
  PolygonPair p = g.make(spec);
  return {spec, std::move(p.a), std::move(p.b), std::nullopt, std::nullopt};
}

namespace {

struct LevelSizes {
  int seeds;
  int kettner_stride;  // grid points i, j step by this (256 / stride per axis)
  std::vector<std::int64_t> blob_n;
  std::vector<std::int64_t> star_n;
  int large_seeds;  // seeds per size for blob and star
  int set_seeds;    // seeds of the set generators (random_set cycles through set_n)
  std::vector<std::int64_t> set_n;
};

LevelSizes sizes_of(SweepLevel level) {
  switch (level) {
    case SweepLevel::quick: return {3, 32, {16, 64, 256, 1024}, {16, 64, 256}, 1, 2, {8, 64}};
    case SweepLevel::normal: return {40, 8, {16, 64, 256, 1024, 4096, 16384}, {16, 64, 256, 512, 1024}, 2, 6, {8, 32, 64}};
    case SweepLevel::full: return {200, 2, {16, 64, 256, 1024, 4096, 16384, 65536}, {16, 64, 256, 1024, 2048, 4096}, 4, 40, {8, 32, 128, 300}};
  }
  return {};
}

}  // namespace

std::vector<CaseSpec> plan_sweep(const PlanOptions& options) {
  const LevelSizes sz = sizes_of(options.level);
  const int seeds = options.seeds > 0 ? options.seeds : sz.seeds;
  std::vector<CaseSpec> out;
  const auto wanted = [&](std::string_view name) {
    if (options.generators.empty()) return true;
    for (const auto& g : options.generators) {
      if (g == name) return true;
    }
    return false;
  };
  for (const auto& name : options.generators) find_generator(name);  // reject unknown names early
  for (const Generator& g : generators()) {
    if (!wanted(g.name)) continue;
    if (options.generators.empty() && is_fill_generator(g.name)) continue;  // on request only
    std::uint64_t index = 0;
    const auto add = [&](std::string_view variant, std::vector<std::pair<std::string, std::int64_t>> params) {
      out.push_back({std::string(g.name), std::string(variant), std::move(params), mix_seed(options.base_seed, g.name, index++)});
    };
    if (g.name == "reported" || g.name == "cases") {
      // Every case of the corpus at every level; `cases` only when the user gave a file.
      for (const auto& c : g.name == "reported" ? reported_corpus() : user_cases()) add(c.id, {});
    } else if (g.name == "kettner_grid") {
      for (const auto v : g.variants) {
        for (int i = 0; i < 256; i += sz.kettner_stride) {
          for (int j = 0; j < 256; j += sz.kettner_stride) add(v, {{"i", i}, {"j", j}});
        }
      }
    } else if (g.name == "ulp_perturbed") {
      for (int s = 0; s < seeds; ++s) {
        for (const auto v : g.variants) {
          for (int k = -8; k <= 8; ++k) add(v, {{"k", k}});
        }
      }
    } else if (g.name == "magnitude") {
      // Each exponent once per seed, the lattice generators taken in turn.
      constexpr std::array<std::int64_t, 9> exponents{-300, -200, -150, -100, 100, 150, 200, 250, 300};
      for (int s = 0; s < seeds; ++s) {
        for (std::size_t k = 0; k < exponents.size(); ++k) {
          add(g.variants[(static_cast<std::size_t>(s) * exponents.size() + k) % g.variants.size()], {{"e", exponents[k]}});
        }
      }
    } else if (g.name == "blob" || g.name == "star") {
      const int large = options.seeds > 0 ? std::min(options.seeds, sz.large_seeds) : sz.large_seeds;
      for (const std::int64_t n : g.name == "blob" ? sz.blob_n : sz.star_n) {
        for (int s = 0; s < large; ++s) add(g.variants[0], {{"n", n}});
      }
    } else if (is_set_generator(g.name)) {
      // Few seeds: these run in every sweep (the default one too), each case a few hundred
      // parts at most; rule 4 (union, the GIS meaning) and 1 (nonzero over all rings at once).
      const int set_seeds = options.seeds > 0 ? options.seeds : sz.set_seeds;
      for (int s = 0; s < set_seeds; ++s) {
        const std::int64_t n = g.name == "random_set" ? sz.set_n[static_cast<std::size_t>(s) % sz.set_n.size()]
                               : g.name == "coverage_grid" ? 4 + 4 * (s % 3)
                                                           : 2 + s % 4;
        for (const auto v : g.variants) {
          for (const std::int64_t rule : {4, 1}) add(v, {{"n", n}, {"rule", rule}});
        }
      }
    } else if (is_fill_generator(g.name)) {
      for (int s = 0; s < seeds; ++s) {
        for (const auto v : g.variants) {
          for (std::int64_t rule = 0; rule < 5; ++rule) add(v, {{"rule", rule}});
        }
      }
    } else if (g.name == "grid_random") {
      for (int s = 0; s < 2 * seeds; ++s) {
        for (const auto v : g.variants) add(v, {{"grid", s % 2 == 0 ? 6 : 10}});
      }
    } else {
      for (int s = 0; s < seeds; ++s) {
        for (const auto v : g.variants) add(v, {});
      }
    }
  }
  return out;
}

}  // namespace mk::experiments
