// The exact predicates (adaptive, interval filter, GMP fallback) against the mpq reference
// on a million random inputs per predicate, drawn at several magnitudes: zero
// disagreements allowed. [Sh97 §4] [MK89 §3.3]
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>

#include "tests/arithmetic/predicate_checker.hpp"

namespace {

using mk::test::PredicateChecker;
using mk::test::random_double;

#ifdef MK_SANITIZE_BUILD
constexpr int cases_per_generator = 40000;  // under the sanitizers (tests/CMakeLists.txt)
#else
constexpr int cases_per_generator = 170000;  // six generators: about 1e6 per predicate
#endif

// A generator fills 8 coordinates (orient2d uses the first 6).
using Generator = std::function<void(std::mt19937_64&, std::array<double, 8>&)>;

struct NamedGenerator {
  const char* name;
  Generator fill;
};

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Nudges v by up to two ulps either way.
double nudge(std::mt19937_64& rng, double v) {
  const int k = std::uniform_int_distribution<int>(-2, 2)(rng);
  for (int i = 0; i < k; ++i) v = std::nextafter(v, HUGE_VAL);
  for (int i = 0; i > k; --i) v = std::nextafter(v, -HUGE_VAL);
  return v;
}

const std::array<NamedGenerator, 6> generators{{
    {"uniform_unit",
     [](std::mt19937_64& rng, std::array<double, 8>& v) {
       for (double& x : v) x = uniform(rng, -1.0, 1.0);
     }},
    // All coordinates within 8x of one random scale 2^e, e in [-1074, 1023]: tiny scales
    // underflow the products, huge ones overflow them.
    {"same_scale",
     [](std::mt19937_64& rng, std::array<double, 8>& v) {
       const int e = std::uniform_int_distribution<int>(-1074, 1023)(rng);
       for (double& x : v) x = random_double(rng, std::max(e - 3, -1074), e);
     }},
    // Every coordinate at its own random scale: mixed magnitudes (1e-300 next to 1e300).
    {"mixed_scale",
     [](std::mt19937_64& rng, std::array<double, 8>& v) {
       for (double& x : v) x = random_double(rng, -1074, 1023);
     }},
    // Nearly collinear points (orient2d) and nearly parallel vectors (orient_vectors): the
    // last point is computed on the line in floating point and nudged by a few ulps.
    {"near_collinear",
     [](std::mt19937_64& rng, std::array<double, 8>& v) {
       const int e = std::uniform_int_distribution<int>(-1000, 1000)(rng);
       const double ax = random_double(rng, e - 4, e), ay = random_double(rng, e - 4, e);
       const double bx = random_double(rng, e - 4, e), by = random_double(rng, e - 4, e);
       const double t = uniform(rng, -2.0, 3.0), s = uniform(rng, -2.0, 3.0);
       v = {ax, ay, bx, by, nudge(rng, ax + t * (bx - ax)), nudge(rng, ay + t * (by - ay)), 0.0, 0.0};
       // orient_vectors(a, b, c, c + s (b - a)): nearly parallel edge directions.
       v[6] = nudge(rng, v[4] + s * (bx - ax));
       v[7] = nudge(rng, v[5] + s * (by - ay));
       // orient_vectors reads (p1, q1, p2, q2) = (v0 v1, v2 v3, v4 v5, v6 v7).
     }},
    // Small integers times 2^e: exact zeros are frequent, at every scale including the
    // subnormal one (integers times 2^-1074 are subnormals, exactly).
    {"small_integers",
     [](std::mt19937_64& rng, std::array<double, 8>& v) {
       const int e = std::uniform_int_distribution<int>(-1074, 1019)(rng);
       for (double& x : v) x = std::ldexp(std::uniform_int_distribution<int>(-8, 8)(rng), e);
     }},
    // Points clustered around a centre, offsets 2^-20 to 2^-50 of it.
    {"clustered",
     [](std::mt19937_64& rng, std::array<double, 8>& v) {
       const int e = std::uniform_int_distribution<int>(-900, 1000)(rng);
       const double cx = random_double(rng, e, e), cy = random_double(rng, e, e);
       for (std::size_t i = 0; i < v.size(); ++i) {
         const int o = std::uniform_int_distribution<int>(20, 50)(rng);
         v[i] = (i % 2 == 0 ? cx : cy) + random_double(rng, e - o, e - o);
       }
     }},
}};

TEST(arith_predicates, orient2d_random_inputs_of_several_magnitudes) {
  for (std::size_t g = 0; g < generators.size(); ++g) {
    const std::uint64_t seed = 1000 + g;
    std::cout << "generator " << generators[g].name << " seed " << seed << "\n";
    std::mt19937_64 rng(seed);
    PredicateChecker check(std::string("orient2d/") + generators[g].name);
    std::array<double, 8> v{};
    for (int k = 0; k < cases_per_generator; ++k) {
      generators[g].fill(rng, v);
      check.orient2d(v[0], v[1], v[2], v[3], v[4], v[5]);
    }
    check.expect_no_disagreement();
  }
}

TEST(arith_predicates, orient_vectors_random_inputs_of_several_magnitudes) {
  for (std::size_t g = 0; g < generators.size(); ++g) {
    const std::uint64_t seed = 2000 + g;
    std::cout << "generator " << generators[g].name << " seed " << seed << "\n";
    std::mt19937_64 rng(seed);
    PredicateChecker check(std::string("orient_vectors/") + generators[g].name);
    std::array<double, 8> v{};
    for (int k = 0; k < cases_per_generator; ++k) {
      generators[g].fill(rng, v);
      check.orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    }
    check.expect_no_disagreement();
  }
}

}  // namespace
