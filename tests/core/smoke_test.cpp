#include <gtest/gtest.h>

#include "arithmetic/kernels/double_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/boolean_op.hpp"

namespace mk {
namespace {

Polygon square(double x0, double y0, double s) {
  return {{{{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}}}, PolygonType::island};
}

TEST(Smoke, OverlappingSquares) {
  for (auto op : {Operation::intersection, Operation::union_, Operation::difference, Operation::symmetric_difference}) {
    auto r = boolean_op<RationalKernel>(square(0, 0, 2), square(1, 1, 2), Options{op, true, EfOrganisation::hash, PairSearch::sweep});
    std::cout << operation_name(op) << ": " << r.cycles.size() << " cycles\n";
    for (auto& c : r.cycles) {
      std::cout << "  " << (c.type == PolygonType::island ? "island" : "hole") << ":";
      for (int v : c.vertices) {
        auto p = RationalKernel::approx(r.vertex(v));
        std::cout << " (" << p.x << "," << p.y << ")";
      }
      std::cout << "\n";
    }
  }
  auto d = boolean_op<DoubleKernel>(square(0, 0, 2), square(1, 1, 2), Options{});
  EXPECT_EQ(d.cycles.size(), 1u);
}

}  // namespace
}  // namespace mk
