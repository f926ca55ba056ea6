// Point-membership tests of semantics [BRIEF §1]: for every result, regular and non-regular,
// of generated pairs of every family (tests/oracle/families.hpp), at every sample point
// (vertices, crossings, points on both boundaries, midpoints of input edge pieces and result
// edges, random points), the exact location in the result is what the operation's definition
// gives from the locations in A and B. Everything is decided by the independent oracle
// (tests/oracle/membership.hpp), nothing by the core's tables; points on both boundaries
// are checked like any other, through their neighbourhoods.
#include <gtest/gtest.h>

#include <iostream>

#include "oracle.hpp"
#include "tests/oracle/families.hpp"

namespace mk::test {
namespace {

constexpr Operation kOps[] = {Operation::intersection, Operation::union_, Operation::difference,
                              Operation::symmetric_difference};

TEST(Semantics, EveryResultAgreesWithTheMembershipOracleAtEverySamplePoint) {
  const std::uint64_t seed = 20261122;
  std::cout << "seed " << seed << "\n";
  oracle::SampleCounts counts;
  int results = 0;
#ifdef MK_SANITIZE_BUILD
  const std::size_t pairs = 12 * oracle::family_names().size();  // under the sanitizers
#else
  const std::size_t pairs = 30 * oracle::family_names().size();
#endif
  for (std::size_t index = 0; index < pairs; ++index) {
    std::mt19937_64 rng(seed + index);
    const oracle::GeneratedPair pair = oracle::random_pair(index, rng);
    const oracle::Region a = oracle::region_of(pair.a);
    const oracle::Region b = oracle::region_of(pair.b);
    for (const Operation op : kOps) {
      for (const bool regular : {true, false}) {
        const Options opt{op, regular, index % 2 ? EfOrganisation::sorted : EfOrganisation::hash, PairSearch::sweep};
        const auto r = boolean_op<RationalKernel>(pair.a, pair.b, opt);
        const oracle::Region result = oracle::region_of(as_input(r));
        const std::string failure = oracle::first_contradiction(
            op, regular, a, b, result, oracle::sample_points(a, b, result, rng, 12), &counts);
        ASSERT_EQ(failure, "") << "pair " << index << " (" << pair.family << ", " << pair.transform << ")\n  A "
                               << oracle::describe(pair.a) << "\n  B " << oracle::describe(pair.b);
        ++results;
      }
    }
  }
  std::cout << results << " results, " << counts.points << " points checked, " << counts.on_both_boundaries
            << " of them on both inputs' boundaries\n";
  // The families put many points on both boundaries: that is where they are meant to test.
  EXPECT_GT(counts.on_both_boundaries, counts.points / 10);
}

}  // namespace
}  // namespace mk::test
