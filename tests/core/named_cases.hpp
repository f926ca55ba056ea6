// Named degenerate cases with their exact expected results, shared by the exact-kernel
// tests (which assert them) and the inexact-kernel tests (which record them). Each name is
// the generator name used in experiments/ (shared_vertex, shared_edge, ...).
#pragma once

#include <string>
#include <vector>

#include "core/polygon.hpp"

namespace mk::test {

struct ExpectedCycle {
  PolygonType type;
  std::vector<Point> vertices;  // in the result's direction of travel
};

struct Expectation {
  Operation op;
  bool regular;
  std::vector<ExpectedCycle> cycles;
  bool unbounded = false;
};

struct NamedCase {
  std::string name;
  Polygon a;
  Polygon b;
  std::vector<Expectation> expect;
};

inline Polygon island(std::vector<Ring> rings) { return {std::move(rings), PolygonType::island}; }
inline Polygon hole_type(std::vector<Ring> rings) { return {std::move(rings), PolygonType::hole}; }
inline Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
inline Ring box_cw(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}}; }
inline ExpectedCycle isl(std::vector<Point> v) { return {PolygonType::island, std::move(v)}; }
inline ExpectedCycle hol(std::vector<Point> v) { return {PolygonType::hole, std::move(v)}; }
inline std::vector<ExpectedCycle> two_sided_ring(const Ring& r) {
  std::vector<ExpectedCycle> out;
  for (std::size_t i = 0; i < r.size(); ++i) out.push_back(isl({r[i], r[(i + 1) % r.size()]}));
  return out;
}

constexpr Operation kI = Operation::intersection;
constexpr Operation kU = Operation::union_;
constexpr Operation kD = Operation::difference;
constexpr Operation kX = Operation::symmetric_difference;

inline std::vector<NamedCase> named_cases() {
  std::vector<NamedCase> cases;
  const Ring sq = box(0, 0, 1, 1);

  cases.push_back({"shared_vertex", island({sq}), island({box(1, 1, 2, 2)}),
                   {{kI, true, {}},
                    {kI, false, {isl({{1, 1}})}},
                    {kU, true, {isl(sq), isl(box(1, 1, 2, 2))}},
                    {kD, true, {isl(sq)}},
                    {kD, false, {isl(sq)}},
                    {kX, true, {isl(sq), isl(box(1, 1, 2, 2))}}}});

  cases.push_back({"shared_edge", island({sq}), island({box(1, 0, 2, 1)}),
                   {{kI, true, {}},
                    {kI, false, {isl({{1, 0}, {1, 1}})}},
                    {kU, true, {isl({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}})}},
                    {kD, true, {isl(sq)}},
                    {kD, false, {isl(sq)}},
                    {kX, true, {isl({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}})}},
                    {kX, false, {isl({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}})}}}});

  // Partially shared collinear edges: opposite directions (B sits on A) ...
  cases.push_back({"collinear_overlap_opposite", island({box(0, 0, 2, 1)}), island({box(1, 1, 3, 2)}),
                   {{kI, true, {}},
                    {kI, false, {isl({{1, 1}, {2, 1}})}},
                    {kU, true, {isl({{0, 0}, {2, 0}, {2, 1}, {3, 1}, {3, 2}, {1, 2}, {1, 1}, {0, 1}})}},
                    {kD, false, {isl({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}})}}}});
  // ... and the same direction (overlapping areas with collinear bottoms).
  cases.push_back({"collinear_overlap_same", island({box(0, 0, 2, 1)}), island({box(1, 0, 3, 2)}),
                   {{kI, true, {isl({{1, 0}, {2, 0}, {2, 1}, {1, 1}})}},
                    {kI, false, {isl({{1, 0}, {2, 0}, {2, 1}, {1, 1}})}},
                    {kU, true, {isl({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 2}, {1, 2}, {1, 1}, {0, 1}})}},
                    {kD, true, {isl({{0, 0}, {1, 0}, {1, 1}, {0, 1}})}},
                    // A - int(B) keeps the shared bottom piece as a dangling edge.
                    {kD, false, {isl({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), isl({{1, 0}, {2, 0}})}}}});

  cases.push_back({"vertex_on_edge", island({{{0, 0}, {2, 0}, {1, 1}}}), island({{{1, 0}, {2, -1}, {3, 0}, {2, 1}}}),
                   {{kI, true, {isl({{1, 0}, {2, 0}, {1.5, 0.5}})}},
                    {kD, true, {isl({{0, 0}, {1, 0}, {1.5, 0.5}, {1, 1}})}}}});

  // Identical polygons: B starts elsewhere and runs the other way.
  cases.push_back({"identical", island({box(0, 0, 2, 2)}), island({{{2, 2}, {2, 0}, {0, 0}, {0, 2}}}),
                   {{kI, true, {isl(box(0, 0, 2, 2))}},
                    {kU, true, {isl(box(0, 0, 2, 2))}},
                    {kD, true, {}},
                    {kD, false, two_sided_ring(box(0, 0, 2, 2))},
                    {kX, true, {}},
                    {kX, false, two_sided_ring(box(0, 0, 2, 2))}}});

  // The same vertex set in another order [MK89 Fig. 7]: the intersection touches itself.
  cases.push_back({"same_vertex_set", island({{{0, 0}, {2, 1}, {4, 0}, {4, 4}, {0, 4}}}),
                   island({{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}}),
                   {{kI, true, {isl({{0, 0}, {2, 1}, {0, 4}}), isl({{2, 1}, {4, 0}, {4, 4}})}},
                    {kU, true, {isl({{0, 0}, {4, 0}, {4, 4}, {0, 4}})}}}});

  // A hole filled exactly by the other polygon.
  cases.push_back({"hole_filled", island({box(0, 0, 3, 3), box(1, 1, 2, 2)}), island({box(1, 1, 2, 2)}),
                   {{kU, true, {isl(box(0, 0, 3, 3))}},
                    {kI, true, {}},
                    {kI, false, two_sided_ring(box(1, 1, 2, 2))},
                    {kD, true, {isl(box(0, 0, 3, 3)), hol(box_cw(1, 1, 2, 2))}},
                    {kX, true, {isl(box(0, 0, 3, 3))}}}});

  // Holes with collinear edges [MK89 Fig. 9]: the holes of A and B share edges.
  cases.push_back({"holes_collinear", island({box(0, 0, 12, 8), box(2, 2, 4, 6), box(6, 2, 10, 6)}),
                   island({box(0, 0, 12, 8), box(4, 2, 6, 6)}),
                   {{kI, true, {isl(box(0, 0, 12, 8)), hol({{2, 2}, {2, 6}, {4, 6}, {6, 6}, {10, 6}, {10, 2}, {6, 2}, {4, 2}})}},
                    {kU, true, {isl(box(0, 0, 12, 8))}}}});

  // Containment touching at a vertex and along an edge.
  cases.push_back({"nested_touching_vertex", island({box(0, 0, 4, 4)}), island({{{0, 0}, {2, 1}, {1, 2}}}),
                   {{kI, true, {isl({{0, 0}, {2, 1}, {1, 2}})}},
                    {kU, true, {isl(box(0, 0, 4, 4))}},
                    {kD, true, {isl(box(0, 0, 4, 4)), hol({{0, 0}, {1, 2}, {2, 1}})}}}});
  cases.push_back({"nested_touching_edge", island({box(0, 0, 4, 4)}), island({{{0, 0}, {2, 0}, {1, 1}}}),
                   {{kI, true, {isl({{0, 0}, {2, 0}, {1, 1}})}},
                    {kD, true, {isl({{0, 0}, {1, 1}, {2, 0}, {4, 0}, {4, 4}, {0, 4}})}}}});

  cases.push_back({"disjoint", island({sq}), island({box(2, 0, 3, 1)}),
                   {{kI, true, {}}, {kI, false, {}}, {kU, true, {isl(sq), isl(box(2, 0, 3, 1))}}, {kD, true, {isl(sq)}}}});
  cases.push_back({"empty_b", island({sq}), island({}),
                   {{kI, true, {}}, {kU, true, {isl(sq)}}, {kD, true, {isl(sq)}}, {kX, true, {isl(sq)}}}});
  cases.push_back({"empty_both", island({}), island({}), {{kI, true, {}}, {kU, true, {}}, {kX, false, {}}}});

  // Hole-type inputs [MK89 §2.2]: regions are closures of complements.
  cases.push_back({"hole_and_island", hole_type({box(0, 0, 1, 1)}), island({box(0, 0, 1, 1)}),
                   {{kU, true, {}, true},
                    {kI, true, {}},
                    {kI, false, two_sided_ring(box(0, 0, 1, 1))},
                    {kD, true, {hol(box(0, 0, 1, 1))}, true}}});
  cases.push_back({"two_holes", hole_type({box(0, 0, 2, 2)}), hole_type({box(1, 1, 3, 3)}),
                   {{kU, true, {hol({{1, 1}, {2, 1}, {2, 2}, {1, 2}})}, true},
                    {kI, true, {hol({{0, 0}, {2, 0}, {2, 1}, {3, 1}, {3, 3}, {1, 3}, {1, 2}, {0, 2}})}, true},
                    // Bounded, with the region on the right of its clockwise outline: an island.
                    {kD, true, {isl({{2, 1}, {2, 2}, {1, 2}, {1, 3}, {3, 3}, {3, 1}})}}}});

  // [MK89 Fig. 10] Collinear overlapping edges; the non-regular intersection has a
  // dangling edge and a single-point result.
  cases.push_back({"paper_fig10", island({box(0, 0, 2, 2)}), island({box(0, 2, 1, 3), box(2, -1, 3, 0)}),
                   {{kI, true, {}},
                    {kI, false, {isl({{0, 2}, {1, 2}}), isl({{2, 0}})}},
                    {kU, true, {isl({{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, 3}, {0, 3}, {0, 2}}), isl(box(2, -1, 3, 0))}}}});
  // [MK89 Fig. 8] A of three irreducible parts, two of its vertices on B's edges: (1, 2) on
  // B's left edge, (4, 1) on its bottom edge (the middle part meets B only there).
  cases.push_back({"paper_fig8", island({{{0, 0}, {2, 0}, {1, 2}}, {{3, 0}, {5, 0}, {4, 1}}, box(6, 0, 8, 2)}),
                   island({{{1, 1}, {7, 1}, {7, 4}, {1, 4}}}),
                   {{kI, true, {isl({{1, 1}, {1.5, 1}, {1, 2}}), isl({{6, 1}, {7, 1}, {7, 2}, {6, 2}})}},
                    {kI, false, {isl({{1, 1}, {1.5, 1}, {1, 2}}), isl({{6, 1}, {7, 1}, {7, 2}, {6, 2}}), isl({{4, 1}})}}}});
  return cases;
}

}  // namespace mk::test
