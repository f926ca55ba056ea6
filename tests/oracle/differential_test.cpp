// The randomized differential test of the exact kernels against independent references:
// `exact` and `rational` must give identical results, every regular result must be the
// region CGAL's exact Boolean operations (Epeck) give (regularized symmetric difference
// empty, exact areas equal as rationals), and every non-regular result must agree with the
// point-membership oracle at every sample point. Inputs come from families.hpp.
// [BRIEF §1] [BRIEF §3] (exact kernels agree on every input) [MK89 §3.1]
// Preconditions: CGAL 5.5 (Debian 12). Environment: MK_ORACLE_SEED (a number, or "random"),
// MK_ORACLE_OPERATIONS (how many operations to check; default 12000 in Release, fewer under
// the sanitizers: see kDefaultOperations); for debugging, MK_ORACLE_VERBOSE (print each
// pair before it runs), MK_ORACLE_GRID (the same pairs left on their integer grid) and
// MK_ORACLE_FIRST (the index of the first pair, to replay a failure).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "tests/oracle/checks.hpp"
#include "tests/oracle/families.hpp"

namespace mk::oracle {
namespace {

// Operations per run: one operation is one (pair, operation, regular) computed by both
// exact kernels and checked. The sanitizer build (ASan + UBSan, -O1) is about 20x slower.
#ifdef MK_SANITIZE_BUILD
constexpr long kDefaultOperations = 800;
#else
constexpr long kDefaultOperations = 12000;
#endif
constexpr std::uint64_t kDefaultSeed = 20261124;

constexpr Operation kOps[] = {Operation::intersection, Operation::union_, Operation::difference,
                              Operation::symmetric_difference};

std::uint64_t seed_from_environment() {
  const char* s = std::getenv("MK_ORACLE_SEED");
  if (s == nullptr || *s == '\0') return kDefaultSeed;
  if (std::string(s) == "random") return std::random_device{}() * 0x9e3779b97f4a7c15ull + std::random_device{}();
  return std::strtoull(s, nullptr, 10);
}

long operations_from_environment() {
  const char* s = std::getenv("MK_ORACLE_OPERATIONS");
  return s != nullptr && *s != '\0' ? std::strtol(s, nullptr, 10) : kDefaultOperations;
}

TEST(Differential, ExactKernelsAgreeWithCgalEpeckAndTheMembershipOracle) {
  const std::uint64_t seed = seed_from_environment();
  const long operations = operations_from_environment();
  std::cout << "MK_ORACLE_SEED=" << seed << " MK_ORACLE_OPERATIONS=" << operations << "\n";
  const auto t0 = std::chrono::steady_clock::now();
  Tally tally;
  std::map<std::string, long> per_family;
  const char* first = std::getenv("MK_ORACLE_FIRST");  // debugging: start at this pair
  for (std::size_t index = first != nullptr ? std::strtoull(first, nullptr, 10) : 0; tally.operations < operations; ++index) {
    std::mt19937_64 rng(seed + 0x9e3779b97f4a7c15ull * index);
    const GeneratedPair pair = random_pair(index, rng);
    const std::string what = "pair " + std::to_string(index) + " (" + pair.family + ", " + pair.transform +
                             ")\n  A " + describe(pair.a) + "\n  B " + describe(pair.b);
    if (std::getenv("MK_ORACLE_VERBOSE") != nullptr) std::cout << what << std::endl;
    const References refs = References::of(pair.a, pair.b);
    for (const Operation op : kOps) {
      for (const bool regular : {true, false}) {
        // Both EF organisations and pair searches take turns.
        const Options opt{op, regular, index % 2 ? EfOrganisation::sorted : EfOrganisation::hash,
                          index % 3 ? PairSearch::sweep : PairSearch::all_pairs};
        const std::string run = what + "\n  " + std::string(operation_name(op)) + (regular ? " regular" : " non-regular");
        const std::string failure = check_operation(pair.a, pair.b, refs, opt, rng, tally, run);
        ASSERT_EQ(failure, "") << run;
        ++per_family[pair.family];
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << tally.operations << " operations in " << seconds << " s: " << tally.regular_vs_cgal
            << " regular results equal to CGAL Epeck's (region and exact area), "
            << tally.operations - tally.regular_vs_cgal << " non-regular results checked at "
            << tally.nonregular_points.points << " sample points (" << tally.nonregular_points.on_both_boundaries
            << " on both inputs' boundaries); CGAL faults shown by the oracle: " << tally.cgal_faults << "\n";
  for (const auto& [family, n] : per_family) std::cout << "  " << family << ": " << n << "\n";
  EXPECT_GE(tally.operations, operations);
}

}  // namespace
}  // namespace mk::oracle
