// mk::compute's errors for input outside the domain: crossing edges come as CrossingEdges,
// carrying both edges, with a message that gives their end points (issue 10, item 5).
// [MK89 §3.3] (crossing edges cannot be repaired)
// Preconditions: none.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "api/mkbool.hpp"

namespace mk {
namespace {

TEST(apiErrors, CrossingEdgesNameBothEdgesWithTheirEndPoints) {
  const Polygon square{{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, PolygonType::island};
  const Polygon bow_tie{{{{0, 0}, {1, 0}, {0, 1}, {1, 1}}}, PolygonType::island};
  for (const auto kernel : kernel_names()) {
    SCOPED_TRACE(std::string(kernel));
    try {
      compute(square, bow_tie, BooleanOptions{Operation::union_, true, std::string(kernel)});
      ADD_FAILURE() << "accepted";
    } catch (const CrossingEdges& e) {
      EXPECT_EQ(e.polygon(), 1);
      EXPECT_EQ(e.first().ring, 0);
      EXPECT_EQ(e.second().ring, 0);
      // The two edges are 3 -> 0 and 1 -> 2, in either order.
      const bool order = e.first().from == 3;
      EXPECT_EQ(order ? e.first().to : e.second().to, 0);
      EXPECT_EQ(order ? e.second().from : e.first().from, 1);
      EXPECT_EQ(std::string(e.what()),
                "polygon B: ring 0's edge from vertex 3 (1 1) to vertex 0 (0 0) crosses ring 0's edge from vertex 1 "
                "(1 0) to vertex 2 (0 1); the edges of a polygon may touch but must not cross");
    }
  }
}

// The edges are named by their own ring, whatever ring comes before them.
TEST(apiErrors, CrossingEdgesOfALaterRingNameThatRing) {
  const Polygon square{{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, PolygonType::island};
  const Polygon shell_and_bow_tie{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{3, 3}, {4, 3}, {3, 4}, {4, 4}}},
                                  PolygonType::island};
  try {
    compute(shell_and_bow_tie, square, BooleanOptions{Operation::union_, true, "exact"});
    ADD_FAILURE() << "accepted";
  } catch (const CrossingEdges& e) {
    EXPECT_EQ(e.polygon(), 0);
    EXPECT_EQ(e.first().ring, 1);
    EXPECT_EQ(e.second().ring, 1);
    const bool order = e.first().from == 3;
    EXPECT_EQ(order ? e.first().to : e.second().to, 0);
    EXPECT_EQ(order ? e.second().from : e.first().from, 1);
    EXPECT_EQ(order ? e.second().to : e.first().to, 2);
  }
}

TEST(apiErrors, NonFiniteCoordinatesAreInvalidInput) {
  const Polygon bad{{{{0, 0}, {1, 0}, {0, std::numeric_limits<double>::infinity()}}}, PolygonType::island};
  EXPECT_THROW(compute(bad, Polygon{}, BooleanOptions{}), InvalidInput);
  EXPECT_THROW(compute(Polygon{}, Polygon{}, BooleanOptions{.kernel = "magic"}), std::invalid_argument);
}

// Every kernel checks the doubles (those that read the input's points without a copy as well
// as the rational ones, which convert them), naming the polygon, ring and vertex.
TEST(apiErrors, EveryKernelNamesTheNonFiniteVertex) {
  const Polygon good{{{{0, 0}, {1, 0}, {0, 1}}}, PolygonType::island};
  for (const double bad_value : {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}) {
    Polygon bad{{{{0, 0}, {1, 0}, {0, 1}}, {{5, 5}, {6, 5}, {5, bad_value}}}, PolygonType::island};
    for (const auto kernel : kernel_names()) {
      SCOPED_TRACE(std::string(kernel));
      for (const bool bad_is_b : {false, true}) {
        try {
          (void)compute(bad_is_b ? good : bad, bad_is_b ? bad : good, BooleanOptions{.kernel = std::string(kernel)});
          ADD_FAILURE() << "no error";
        } catch (const InvalidInput& e) {
          EXPECT_EQ(std::string(e.what()),
                    std::string("polygon ") + (bad_is_b ? "B" : "A") + ", ring 1, vertex 2: coordinate is not finite");
        }
      }
    }
  }
}

}  // namespace
}  // namespace mk
