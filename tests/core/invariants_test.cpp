// Exact invariants over generated pairs, both argument orders: areas, commutativity,
// (A - B) u (A n B) = A, A xor B = (A u B) - (A n B), results vertex-complete and uncrossed.
#include <gtest/gtest.h>

#include <iostream>

#include "generators.hpp"
#include "predicates/segments.hpp"

namespace mk::test {
namespace {

using R = BooleanResult<RationalKernel>;
using QPoly = BasicPolygon<RationalPoint>;

template <class P>
R run(const P& a, const P& b, Operation op, bool regular = true) {
  return boolean_op<RationalKernel>(a, b, Options{op, regular, EfOrganisation::hash, PairSearch::sweep});
}

QPoly exact(const Polygon& p) { return to_kernel_polygon<RationalKernel>(p); }

bool is_empty(const R& r) { return r.cycles.empty() && !r.unbounded; }

// Same region: their regular symmetric difference is empty.
bool same_region(const QPoly& x, const QPoly& y) { return is_empty(run(x, y, Operation::symmetric_difference)); }

// No two result edges cross properly, no vertex lies strictly inside an edge, and area
// cycles have distinct vertices.
void expect_vertex_complete(const R& r, const std::string& what) {
  std::vector<std::pair<QPoint, QPoint>> edges;
  std::vector<QPoint> vertices;
  for (const auto& c : r.cycles) {
    for (std::size_t i = 0; i < c.vertices.size(); ++i) {
      vertices.push_back(r.vertex(c.vertices[i]));
      if (c.vertices.size() > 1) edges.push_back({r.vertex(c.vertices[i]), r.vertex(c.vertices[(i + 1) % c.vertices.size()])});
    }
    std::vector<int> sorted = c.vertices;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << what << ": repeated vertex";
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto rel = relate_segments<RationalKernel>(edges[i].first, edges[i].second, edges[j].first, edges[j].second);
      ASSERT_FALSE(rel.proper_crossing) << what << ": result edges cross";
    }
    for (const auto& v : vertices) {
      if (v == edges[i].first || v == edges[i].second) continue;
      ASSERT_FALSE(on_segment(edges[i].first, edges[i].second, v)) << what << ": vertex inside an edge";
    }
  }
}

TEST(Invariants, AreasAndIdentitiesOnRandomGridPairs) {
  const std::uint64_t seed = 7700331;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  int pairs = 0;
  for (int iter = 0; iter < 150; ++iter) {
    const Polygon pa = random_polygon(rng, iter % 3 == 0);
    const Polygon pb = random_polygon(rng, iter % 5 == 0);
    const std::string what = "iter " + std::to_string(iter) + " A=" + describe(pa) + " B=" + describe(pb);
    const QPoly a = exact(pa);
    const QPoly b = exact(pb);
    ++pairs;
    for (int order = 0; order < 2; ++order) {
      const QPoly& x = order == 0 ? a : b;
      const QPoly& y = order == 0 ? b : a;
      const R inter = run(x, y, Operation::intersection);
      const R uni = run(x, y, Operation::union_);
      const R diff = run(x, y, Operation::difference);
      const R sym = run(x, y, Operation::symmetric_difference);
      for (const R* r : {&inter, &uni, &diff, &sym}) expect_vertex_complete(*r, what);
      for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                                 Operation::symmetric_difference}) {
        expect_vertex_complete(run(x, y, op, false), what + " non-regular " + std::string(operation_name(op)));
      }
      if (x.type == PolygonType::island && y.type == PolygonType::island) {
        const Q ax = area(to_qrings(order == 0 ? pa : pb));
        const Q ay = area(to_qrings(order == 0 ? pb : pa));
        EXPECT_EQ(area(uni) + area(inter), ax + ay) << what;
        EXPECT_EQ(area(diff) + area(inter), ax) << what;
        EXPECT_EQ(area(sym), area(uni) - area(inter)) << what;
      }
      // Commutativity of intersection and union.
      EXPECT_TRUE(same_region(as_input(inter), as_input(run(y, x, Operation::intersection)))) << what;
      EXPECT_TRUE(same_region(as_input(uni), as_input(run(y, x, Operation::union_)))) << what;
      // (A - B) u (A n B) = A.
      EXPECT_TRUE(same_region(as_input(run(as_input(diff), as_input(inter), Operation::union_)), x)) << what;
      // A xor B = (A u B) - (A n B).
      EXPECT_TRUE(same_region(as_input(sym), as_input(run(as_input(uni), as_input(inter), Operation::difference))))
          << what;
    }
  }
  std::cout << pairs << " pairs\n";
}

TEST(Invariants, EfOrganisationsAgree) {
  std::mt19937_64 rng(99);
  for (int iter = 0; iter < 100; ++iter) {
    const Polygon a = random_polygon(rng, true);
    const Polygon b = random_polygon(rng, true);
    for (const bool regular : {true, false}) {
      for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                                 Operation::symmetric_difference}) {
        const auto h = boolean_op<RationalKernel>(a, b, Options{op, regular, EfOrganisation::hash, PairSearch::sweep});
        const auto s = boolean_op<RationalKernel>(a, b, Options{op, regular, EfOrganisation::sorted, PairSearch::all_pairs});
        // Same region and same irreducible parts (as sets of vertex cycles).
        ASSERT_EQ(h.cycles.size(), s.cycles.size());
        EXPECT_EQ(area(h), area(s));
        EXPECT_TRUE(same_region(as_input(h), as_input(s)));
      }
    }
  }
}

}  // namespace
}  // namespace mk::test
