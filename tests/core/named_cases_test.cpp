// Named degenerate cases: exact kernels must give exactly the expected irreducible polygons
// and types; the double kernel runs them too and its results are recorded, not asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "arithmetic/kernels/double_kernel.hpp"
#include "canonical.hpp"

namespace mk::test {
namespace {

TEST(NamedCases, RationalKernelGivesExactlyTheExpectedPolygons) {
  int checked = 0;
  for (const auto& nc : named_cases()) {
    for (const auto& e : nc.expect) {
      for (const auto ef : {EfOrganisation::hash, EfOrganisation::sorted}) {
        for (const auto search : {PairSearch::sweep, PairSearch::all_pairs}) {
          const auto r = boolean_op<RationalKernel>(nc.a, nc.b, Options{e.op, e.regular, ef, search});
          EXPECT_EQ(show(canonical(r)), show(canonical(e.cycles)))
              << nc.name << " " << operation_name(e.op) << (e.regular ? " regular" : " non-regular");
          EXPECT_EQ(r.unbounded, e.unbounded) << nc.name << " " << operation_name(e.op);
          ++checked;
        }
      }
    }
  }
  std::cout << checked << " expectations checked\n";
}

// Swapping the arguments of an intersection or union gives the same polygons.
TEST(NamedCases, BothArgumentOrders) {
  for (const auto& nc : named_cases()) {
    for (const auto op : {Operation::intersection, Operation::union_}) {
      for (const bool regular : {true, false}) {
        const auto ab = boolean_op<RationalKernel>(nc.a, nc.b, Options{op, regular, EfOrganisation::hash, PairSearch::sweep});
        const auto ba = boolean_op<RationalKernel>(nc.b, nc.a, Options{op, regular, EfOrganisation::hash, PairSearch::sweep});
        if (nc.a.type != nc.b.type) continue;  // types decide the orientation of the output
        EXPECT_EQ(show(canonical(ab)), show(canonical(ba))) << nc.name << " " << operation_name(op);
      }
    }
  }
}

// The naive kernel runs every named case to a result or a KernelFailure (inconsistent
// predicates, reported), never another exception or a crash; its disagreements are data.
TEST(NamedCases, DoubleKernelGivesAResultOrAKernelFailure) {
  int agree = 0, differ = 0, failed = 0;
  for (const auto& nc : named_cases()) {
    for (const auto& e : nc.expect) {
      try {
        const auto r = boolean_op<DoubleKernel>(nc.a, nc.b, Options{e.op, e.regular, EfOrganisation::hash, PairSearch::sweep});
        if (show(canonical(r)) == show(canonical(e.cycles))) {
          ++agree;
        } else {
          ++differ;
          std::cout << "double differs: " << nc.name << " " << operation_name(e.op) << "\n";
        }
      } catch (const KernelFailure& ex) {
        ++failed;
        std::cout << "double failed: " << nc.name << ": " << ex.what() << "\n";
      } catch (const std::exception& ex) {
        ADD_FAILURE() << "double kernel on " << nc.name << ": not a KernelFailure: " << ex.what();
      }
    }
  }
  std::cout << "double kernel on named cases: " << agree << " agree, " << differ << " differ, " << failed
            << " kernel failures\n";
}

}  // namespace
}  // namespace mk::test
