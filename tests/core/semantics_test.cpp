// Point-membership tests of semantics (BRIEF.md section 1): at every sample point the
// exact location in the result equals what the set operation gives from A and B.
#include <gtest/gtest.h>

#include <iostream>

#include "generators.hpp"

namespace mk::test {
namespace {

constexpr Operation kOps[] = {Operation::intersection, Operation::union_, Operation::difference,
                              Operation::symmetric_difference};

// The sample points: every vertex, the midpoint of every edge fragment (their ends as the
// trace hook saw them after step 4: the result keeps vertices, not fragments), and random
// grid points.
std::vector<QPoint> sample_points(const BooleanResult<RationalKernel>& r,
                                  const std::vector<std::pair<int, int>>& fragment_ends, std::mt19937_64& rng) {
  std::vector<QPoint> s;
  for (int v = 0; v < r.arrangement.num_vertices(); ++v) s.push_back(r.vertex(v));
  for (const auto& [from, to] : fragment_ends) {
    const auto& a = r.vertex(from);
    const auto& b = r.vertex(to);
    s.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
  }
  std::uniform_int_distribution<int> grid(-8, 60);
  for (int i = 0; i < 60; ++i) {
    QPoint q{Q(grid(rng), 4), Q(grid(rng), 4)};
    q.x.canonicalize();
    q.y.canonicalize();
    s.push_back(q);
  }
  return s;
}

bool in(Location l) { return l != Location::outside; }
bool interior(Location l) { return l == Location::inside; }

TEST(Semantics, PointMembershipOnRandomGridPairs) {
  const std::uint64_t seed = 20261122;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  int cases = 0;
  int skipped = 0;
  long checked = 0;
  for (int iter = 0; iter < 400; ++iter) {
    const Polygon a = random_polygon(rng, true);
    const Polygon b = random_polygon(rng, true);
    const auto qa = to_qrings(a);
    const auto qb = to_qrings(b);
    for (const Operation op : kOps) {
      for (const bool regular : {true, false}) {
        for (const auto ef : {EfOrganisation::hash, EfOrganisation::sorted}) {
          BooleanResult<RationalKernel> r;
          std::vector<std::pair<int, int>> fragment_ends;
          const TraceHook<RationalKernel> keep_fragments = [&](Step step, const Arrangement<RationalKernel>& arr) {
            if (step != Step::classified) return;
            for (const auto& poly : arr.polygon) {
              for (const auto& f : poly.fragments) fragment_ends.push_back({f.from, f.to});
            }
          };
          try {
            r = boolean_op<RationalKernel>(a, b, Options{op, regular, ef, PairSearch::sweep}, keep_fragments);
          } catch (const InvalidInput&) {
            ++skipped;  // the generator made a polygon with crossing rings
            goto next_pair;
          }
          ++cases;
          EXPECT_FALSE(fragment_ends.empty());
          for (const QPoint& p : sample_points(r, fragment_ends, rng)) {
            const Location la = locate(qa, a.type, p);
            const Location lb = locate(qb, b.type, p);
            const Location lr = locate(r, p);
            ++checked;
            if (!regular) {
              const bool expect = is_in_closed_result(op, in(la), interior(la), in(lb), interior(lb));
              ASSERT_EQ(in(lr), expect) << "iter " << iter << " op " << operation_name(op) << " non-regular at ("
                                        << p.x << ", " << p.y << ")";
              continue;
            }
            if (la == Location::boundary && lb == Location::boundary) continue;  // needs neighbourhoods
            // Faces on the two sides of p (equal when p is on neither boundary).
            const bool a1 = in(la) , a0 = interior(la);
            const bool b1 = in(lb), b0 = interior(lb);
            const int sides = is_face_in_result(op, a1, b1) + is_face_in_result(op, a0, b0);
            const Location expect = sides == 2 ? Location::inside : (sides == 1 ? Location::boundary : Location::outside);
            ASSERT_EQ(static_cast<int>(lr), static_cast<int>(expect))
                << describe(a) << " " << describe(b) << " la " << int(la) << " lb " << int(lb) << " iter " << iter << " op " << operation_name(op) << " regular at (" << p.x << ", " << p.y << ")";
          }
        }
      }
    }
  next_pair:;
  }
  std::cout << cases << " cases, " << skipped << " skipped inputs, " << checked << " points checked\n";
  EXPECT_GT(cases, 2000);
}

}  // namespace
}  // namespace mk::test
