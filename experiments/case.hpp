// A generated experiment case: the spec that reproduces it (generator, variant, integer
// parameters, seed) and the two input polygons A and B, or for a set case the parts of an
// N-ary operation. [MK89 §2.2] (polygon model)
// Preconditions: none; a spec is plain data, written to and read from CSV rows.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/polygon.hpp"

namespace mk::experiments {

struct CaseSpec {
  std::string generator;
  std::string variant;  // a named sub-configuration of the generator
  std::vector<std::pair<std::string, std::int64_t>> params;  // e.g. {"k", -3}, {"n", 256}
  std::uint64_t seed = 0;

  std::int64_t param(std::string_view name, std::int64_t fallback = 0) const;
  // "k=-3;n=256" (the CSV's params column); parse_params reads it back.
  std::string params_text() const;
  // generator_seed plus the variant and parameters: a file name stem unique in a sweep.
  std::string stem() const;
};

std::vector<std::pair<std::string, std::int64_t>> parse_params(std::string_view text);

struct PolygonPair {
  Polygon a;
  Polygon b;
};

struct Case {
  CaseSpec spec;
  Polygon a;
  Polygon b;
  // External cases (reported, --cases): the inputs' OGC structure exactly as given, which
  // the peer libraries take; generated cases get theirs from the rings' nesting (ogc.hpp).
  std::optional<MultiPolygon> a_ogc;
  std::optional<MultiPolygon> b_ogc;
  // Set cases (generators_set.cpp): the parts of union_all and intersection_all, as given
  // (overlapping, sharing edges). A then holds all their rings as the case's fill rule reads
  // them (mk::fill_rule_polygon), for sizes and pictures, and B is empty: the pair shape of
  // every other case, so that rows, pictures and reports need no second kind of case.
  std::optional<MultiPolygon> parts = std::nullopt;
  std::size_t size() const;  // input vertices of A and B together
};

// The random engine of one case: std::mt19937_64 seeded with the case's seed only.
inline std::mt19937_64 case_rng(const CaseSpec& spec) { return std::mt19937_64(spec.seed); }

// A double uniform in [0, 1) from 53 random bits, the same on every platform (unlike
// std::uniform_real_distribution).
inline double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

// SplitMix64: derives the seeds of a sweep's cases from its one base seed.
std::uint64_t mix_seed(std::uint64_t base, std::string_view generator, std::uint64_t index);

}  // namespace mk::experiments
