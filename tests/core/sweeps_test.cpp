// The searches behind the near-linear time of the operation, each against a brute-force
// definition: candidate pairs (core/pairs.hpp) against every pair of meeting segments, the
// batch locator (core/locator.hpp) against one ray scan per query, the shells of holes
// (core/assemble.hpp) against exact point location in every island; and the operation on
// several threads against one thread, bit for bit. [MK89 §4.3] [MK89 §2.2]
// Preconditions: none; seeds are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <set>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/assemble.hpp"
#include "core/boolean_op.hpp"
#include "core/clean_edges.hpp"
#include "core/locator.hpp"
#include "core/pairs.hpp"
#include "core/prepare.hpp"
#include "core/red_blue.hpp"
#include "core/to_output.hpp"
#include "generators.hpp"
#include "oracle.hpp"

namespace mk::test {
namespace {

using K = ExactKernel;

Ring square_ring(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// Rings whose segments meet in every way: grid stars, nested squares touching along their
// sides, full-width stripes, a comb over a long edge, grid squares touching at corners.
std::vector<Polygon> segment_soups(std::mt19937_64& rng) {
  std::vector<Polygon> out;
  for (int i = 0; i < 6; ++i) out.push_back(random_polygon(rng, false));
  Polygon nested;
  for (int k = 1; k <= 12; ++k) nested.rings.push_back(square_ring(-k, -k, k, k));
  out.push_back(nested);
  Polygon stripes;
  for (int k = 0; k < 30; ++k) stripes.rings.push_back(square_ring(0, 2 * k, 100, 2 * k + 1 + (k % 3 == 0)));
  out.push_back(stripes);
  Polygon comb;
  comb.rings.emplace_back();
  comb.rings[0].push_back({0, 0});
  for (int k = 0; k < 200; ++k) comb.rings[0].push_back({0.5 * k, k % 2 == 0 ? 1.0 : 2.0});
  comb.rings[0].push_back({100, 0});
  out.push_back(comb);
  Polygon grid;
  for (int j = 0; j < 14; ++j) {
    for (int i = j % 2; i < 14; i += 2) grid.rings.push_back(square_ring(i, j, i + 1, j + 1));
  }
  out.push_back(grid);
  return out;
}

// Point ids, x-ranks and sweep items of the rings of polygons a and b (groups 0 and 1).
struct Items {
  std::vector<K::Point> pts;
  std::vector<int> x_rank;
  std::vector<SweepItem> items;
};

Items items_of(const Polygon& a, const Polygon& b) {
  Items out;
  std::vector<Point> all;
  for (const auto* p : {&a, &b}) {
    for (const auto& r : p->rings) all.insert(all.end(), r.begin(), r.end());
  }
  std::sort(all.begin(), all.end(), [](const Point& u, const Point& w) { return u.x != w.x ? u.x < w.x : u.y < w.y; });
  all.erase(std::unique(all.begin(), all.end()), all.end());
  out.pts = all;
  out.x_rank.resize(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) out.x_rank[i] = i == 0 ? 0 : out.x_rank[i - 1] + (all[i].x != all[i - 1].x);
  const auto id = [&](const Point& q) {
    return static_cast<int>(std::lower_bound(all.begin(), all.end(), q, [](const Point& u, const Point& w) {
                              return u.x != w.x ? u.x < w.x : u.y < w.y;
                            }) -
                            all.begin());
  };
  int group = 0;
  for (const auto* p : {&a, &b}) {
    for (const auto& r : p->rings) {
      for (std::size_t k = 0; k < r.size(); ++k) {
        const int u = id(r[k]);
        const int w = id(r[(k + 1) % r.size()]);
        if (u != w) out.items.push_back(sweep_item(u, w, group, k > 0));
      }
    }
    ++group;
  }
  return out;
}

bool boxes_meet(const Items& s, const SweepItem& a, const SweepItem& b) {
  const auto& p = s.pts;
  const auto y_range = [&](const SweepItem& it) { return std::minmax(p[it.lo].y, p[it.hi].y); };
  const auto [a0, a1] = y_range(a);
  const auto [b0, b1] = y_range(b);
  return p[a.lo].x <= p[b.hi].x && p[b.lo].x <= p[a.hi].x && a0 <= b1 && b0 <= a1;
}

// The segment soups drawn from `seed`, which is printed.
std::vector<Polygon> soups_from(std::uint64_t seed) {
  std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  return segment_soups(rng);
}

TEST(CandidatePairs, ReportEveryMeetingPairOnceAndNoPairOfApartBoxes) {
  const std::vector<Polygon> soups = soups_from(20261125);
  int checked = 0;
  for (std::size_t i = 0; i < soups.size(); ++i) {
    for (std::size_t j = 0; j < soups.size(); ++j) {
      if (j != i && j != (i + 3) % soups.size()) continue;
      const Items s = items_of(soups[i], soups[j]);
      for (const bool bipartite : {false, true}) {
        CandidatePairs<K> pairs(s.pts, s.x_rank, s.items, bipartite, PairSearch::sweep);
        std::set<std::pair<int, int>> found;
        for (std::size_t part = 0; part < pairs.parts(); ++part) {
          pairs.for_each_in_part(part, [&](int a, int b) {
            const auto key = std::minmax(a, b);
            EXPECT_TRUE(found.insert(key).second) << "pair reported twice: " << a << " " << b;
            EXPECT_TRUE(boxes_meet(s, s.items[a], s.items[b]));
            if (bipartite) {
              EXPECT_NE(s.items[a].group, s.items[b].group);
            }
          });
        }
        // Every two segments that meet (but consecutive segments of one ring at their shared
        // end) are among the pairs.
        for (int a = 0; a < static_cast<int>(s.items.size()); ++a) {
          for (int b = a + 1; b < static_cast<int>(s.items.size()); ++b) {
            const SweepItem& x = s.items[a];
            const SweepItem& y = s.items[b];
            if (bipartite && x.group == y.group) continue;
            const auto rel = relate_segments_by_id<K>(s.pts, x.lo, x.hi, y.lo, y.hi);
            const bool same = x.lo == y.lo && x.hi == y.hi;
            if (!rel.proper_crossing && !rel.touches() && !same) continue;
            ++checked;
            EXPECT_TRUE(found.count({a, b})) << "soups " << i << "," << j << " missed segments " << a << " " << b;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(WindingLocator, BatchSweepEqualsScanPerQuery) {
  const std::uint64_t seed = 41;
  std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  const std::vector<Polygon> soups = segment_soups(rng);
  int compared = 0;
  for (std::size_t i = 0; i < soups.size(); ++i) {
    for (std::size_t j = 0; j < soups.size(); ++j) {
      if (j != (i + 1) % soups.size()) continue;
      // Located: polygon i (prepared, so its edges do not cross); queries beside every edge
      // of both polygons, on both sides.
      Arrangement<K> arr;
      try {
        arr = prepare<K>(soups[i], soups[j]);
      } catch (const InvalidInput&) {
        continue;  // a soup whose own edges cross (random stars may)
      }
      std::vector<Edge> edges;
      for (const auto& c : arr.polygon[0].cycles) {
        for (std::size_t k = 0; k < c.size(); ++k) edges.push_back({c[k], c[(k + 1) % c.size()]});
      }
      std::vector<LocatorQuery> queries;
      for (const auto& poly : arr.polygon) {
        for (const auto& c : poly.cycles) {
          for (std::size_t k = 0; k < c.size(); ++k) {
            queries.push_back({c[k], c[(k + 1) % c.size()], Side::left});
            queries.push_back({c[(k + 1) % c.size()], c[k], Side::right});
          }
        }
      }
      const WindingLocator<K> locator(arr, edges);
      const std::vector<int> windings = locator.windings(queries);
      const std::vector<int> parities = locator.crossing_parities(queries);
      for (std::size_t q = 0; q < queries.size(); ++q) {
        const LocatorQuery& x = queries[q];
        ASSERT_EQ(windings[q], locator.winding(x.v, x.t, x.side)) << "soup " << i << " query " << q;
        ASSERT_EQ(parities[q] % 2, locator.crossings(x.v, x.t, x.side) % 2) << "soup " << i << " query " << q;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 2000);
}

// BlockedOrder against std::set under random insertions and erasures of thousands of ints,
// so that blocks split, empty and are removed: after each change, next(e) is the element
// after e in the set for sampled e (across block boundaries too), and insert returns it.
TEST(BlockedOrder, NextAndInsertAgreeWithAnOrderedSet) {
  const std::uint64_t seed = 5;
  std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> value(0, 20'000);
  detail::BlockedOrder order;
  std::set<int> set;
  const auto less = [](int a, int b) { return a < b; };
  const auto after = [&](int e) {
    const auto it = set.upper_bound(e);
    return it == set.end() ? -1 : *it;
  };
  int checked = 0;
  for (int step = 0; step < 30'000; ++step) {
    const int e = value(rng);
    const bool grow = step < 15'000 ? step % 4 != 3 : step % 4 == 3;  // fill, then drain
    if (set.count(e) == 0 && grow) {
      set.insert(e);
      ASSERT_EQ(order.insert(e, less), after(e)) << "step " << step;
    } else if (set.count(e) != 0 && !grow) {
      set.erase(e);
      order.erase(e, less);
    }
    if (step % 50 == 0 && !set.empty()) {
      for (const int x : set) {
        ASSERT_EQ(order.next(x, less), after(x)) << "step " << step << " element " << x;
        ++checked;
      }
    }
  }
  EXPECT_GT(set.size(), 0u);
  EXPECT_GT(checked, 1'000'000);
}

// Concentric square annuli, each shifted a little at random, against the same: results with
// many islands inside holes inside islands.
Polygon annuli(std::mt19937_64& rng, int n, double shift) {
  std::uniform_int_distribution<int> jitter(0, 2);
  Polygon p;
  for (int k = 0; k < n; ++k) {
    const double s = 4 * k + shift + 0.25 * jitter(rng);
    p.rings.push_back(square_ring(-s - 3, -s - 3, s + 3, s + 3));
    Ring hole = square_ring(-s - 1, -s - 1, s + 1, s + 1);
    std::reverse(hole.begin(), hole.end());
    p.rings.push_back(hole);
  }
  return p;
}

// Every hole's shell from inclusion_parents against the innermost island around the midpoint
// of its first edge, found by exact point location in every island: `rings` annuli per
// polygon, `rounds` random inputs, each operation. Returns the number of holes checked.
int check_innermost_shells(std::uint64_t seed, int rings_per_polygon, int rounds) {
  std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  int holes = 0;
  for (int round = 0; round < rounds; ++round) {
    const Polygon a = annuli(rng, rings_per_polygon, 0);
    const Polygon b = annuli(rng, rings_per_polygon, round % 2 == 0 ? 1.5 : 0.75);
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                               Operation::symmetric_difference}) {
      const auto r = boolean_op<RationalKernel>(a, b, Options{op});
      const std::vector<int> parent = inclusion_parents(r.arrangement, r.cycles);
      std::vector<QRing> rings(r.cycles.size());
      for (std::size_t c = 0; c < r.cycles.size(); ++c) {
        for (const int v : r.cycles[c].vertices) rings[c].push_back(r.vertex(v));
      }
      const auto area = [&](std::size_t c) {
        Q twice = 0;
        for (std::size_t k = 0; k < rings[c].size(); ++k) twice += cross(QPoint{0, 0}, rings[c][k], rings[c][(k + 1) % rings[c].size()]);
        return Q(abs(twice));
      };
      for (std::size_t h = 0; h < r.cycles.size(); ++h) {
        if (r.cycles[h].type != PolygonType::hole || rings[h].size() < 3) continue;
        // The midpoint of the hole's first edge lies on no other cycle (they share no edge).
        const QPoint m{(rings[h][0].x + rings[h][1].x) / 2, (rings[h][0].y + rings[h][1].y) / 2};
        int expected = -1;
        for (std::size_t c = 0; c < r.cycles.size(); ++c) {
          if (r.cycles[c].type != PolygonType::island || rings[c].size() < 3 ||
              locate(std::vector<QRing>{rings[c]}, PolygonType::island, m) != Location::inside) {
            continue;
          }
          if (expected < 0 || area(c) < area(static_cast<std::size_t>(expected))) expected = static_cast<int>(c);
        }
        EXPECT_EQ(parent[h], expected) << "round " << round << " op " << operation_name(op) << " hole " << h;
        ++holes;
      }
    }
  }
  return holes;
}

TEST(InclusionParents, ShellIsTheInnermostIslandAroundEachHole) { EXPECT_GT(check_innermost_shells(7, 6, 12), 100); }

// Deep nesting: hundreds of edges cross the sweep line at once, so the sweep's ordered
// blocks (BlockedOrder, at most 128 edges each) split and the neighbour above a hole's
// edge is often in the next block.
TEST(InclusionParents, ShellOfEachHoleInHundredsOfNestedRings) { EXPECT_GT(check_innermost_shells(11, 150, 2), 1000); }

// Inputs of tens of thousands of vertices, so that every parallel phase runs on threads
// (core/parallel.hpp: kParallelWork).
// A disc of n vertices about (cx, cy) whose radius waves `lobes` times around it.
Polygon wavy_disc(int n, int lobes, double cx, double cy) {
  Ring r;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    const double radius = 100 * (1 + 0.1 * std::sin(lobes * t));
    r.push_back({cx + radius * std::cos(t), cy + radius * std::sin(t)});
  }
  return Polygon{{r}, PolygonType::island};
}

// Contour-like nested rings: `n` annuli of two `m`-point wavy rings each, around (cx, cy),
// their segments much longer than the rings' spacing at the outside, so that boxes of
// segments and of chains overlap many others that they never meet.
Polygon nested_wavy_rings(int n, int m, double cx, double cy, double phase) {
  Polygon p;
  for (int k = 0; k < n; ++k) {
    for (const double r : {2.0 * k + 1.6, 2.0 * k + 1.0}) {
      Ring ring;
      for (int i = 0; i < m; ++i) {
        const double t = 2 * std::numbers::pi * i / m;
        const double radius = r + 0.1 * std::sin(7 * t + phase + k);
        ring.push_back({cx + radius * std::cos(t), cy + radius * std::sin(t)});
      }
      if (r < 2.0 * k + 1.5) std::reverse(ring.begin(), ring.end());  // the inner ring: a hole
      p.rings.push_back(ring);
    }
  }
  return p;
}

std::vector<std::pair<std::string, std::pair<Polygon, Polygon>>> large_inputs() {
  std::vector<std::pair<std::string, std::pair<Polygon, Polygon>>> out;
  out.push_back({"blob", {wavy_disc(12000, 5, 0, 0), wavy_disc(12000, 5, 30, 10)}});
  Polygon grid_a, grid_b;
  for (int j = 0; j < 80; ++j) {
    for (int i = j % 2; i < 80; i += 2) {
      grid_a.rings.push_back(square_ring(i, j, i + 1, j + 1));
      grid_b.rings.push_back(square_ring(i + 0.5, j + 0.5, i + 1.5, j + 1.5));
    }
  }
  out.push_back({"checkerboard_offset", {grid_a, grid_b}});
  std::mt19937_64 rng(3);
  out.push_back({"annuli", {annuli(rng, 1100, 0), annuli(rng, 1100, 1.5)}});
  std::uniform_real_distribution<double> u(0, 1);
  const auto star = [&](int n, double cx, double cy) {
    std::vector<double> angles(n);
    for (auto& t : angles) t = 2 * std::numbers::pi * u(rng);
    std::sort(angles.begin(), angles.end());
    Ring r;
    for (const double t : angles) {
      const double radius = 97 + 3 * u(rng);  // thousands of crossings, not millions
      r.push_back({cx + radius * std::cos(t), cy + radius * std::sin(t)});
    }
    return Polygon{{r}, PolygonType::island};
  };
  out.push_back({"star", {star(9000, 0, 0), star(9000, 32, 0)}});
  // The preparation's box search runs out of its budget here and the sweep over both takes
  // over (core/red_blue.hpp).
  out.push_back({"nested_wavy_rings", {nested_wavy_rings(160, 32, 0, 0, 0), nested_wavy_rings(160, 32, 0.7, 0.3, 1)}});
  return out;
}

// Appends each segment soup paired with the soup `shift` places on, then `randoms` pairs of
// random polygons.
void add_soups_and_random_pairs(std::mt19937_64& rng, std::size_t shift, int randoms,
                                std::vector<std::pair<std::string, std::pair<Polygon, Polygon>>>& inputs) {
  const std::vector<Polygon> soups = segment_soups(rng);
  for (std::size_t i = 0; i < soups.size(); ++i) {
    inputs.push_back({"soup " + std::to_string(i), {soups[i], soups[(i + shift) % soups.size()]}});
  }
  for (int k = 0; k < randoms; ++k) {
    inputs.push_back({"random " + std::to_string(k), {random_polygon(rng, true), random_polygon(rng, true)}});
  }
}

// The chains are made in two halves on two threads (cut at a ring's start) once the items
// are many: the parts and their pairs must come out as on one thread, in the same order.
TEST(CandidatePairs, SamePairsInTheSameOrderOnOneAndTwoThreads) {
  for (const auto& [name, inputs] : large_inputs()) {
    const Items s = items_of(inputs.first, inputs.second);
    ASSERT_GE(s.items.size(), kParallelWork) << name << ": too few items to make the chains on two threads";
    for (const bool bipartite : {false, true}) {
      std::vector<std::vector<std::pair<int, int>>> runs;
      for (const unsigned threads : {1u, 2u}) {
        CandidatePairs<K> pairs(s.pts, s.x_rank, s.items, bipartite, PairSearch::sweep, threads);
        std::vector<std::pair<int, int>> all;
        for (std::size_t part = 0; part < pairs.parts(); ++part) {
          pairs.for_each_in_part(part, [&](int a, int b) { all.emplace_back(a, b); });
          all.emplace_back(-1, static_cast<int>(part));  // where each part ends
        }
        runs.push_back(std::move(all));
      }
      EXPECT_GT(std::count_if(runs[0].begin(), runs[0].end(), [](const auto& p) { return p.first >= 0; }), 0) << name;
      EXPECT_EQ(runs[0], runs[1]) << name << (bipartite ? ", bipartite" : "");
    }
  }
}

// A result's cycles, island or hole, each vertex's exact coordinates in cycle order.
std::string cycles_text(const BooleanResult<K>& r) {
  std::string text;
  for (const auto& c : r.cycles) {
    text += c.type == PolygonType::island ? "I" : "H";
    for (const int v : c.vertices) {
      const auto e = K::exact_coordinates(r.vertex(v));
      text += " " + e[0] + "," + e[1];
    }
    text += "\n";
  }
  return text;
}

TEST(Threads, ResultsAreTheSameBitForBitOnAnyNumberOfThreads) {
  for (const auto& [name, inputs] : large_inputs()) {
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::symmetric_difference}) {
      std::vector<std::string> seen;
      for (const unsigned threads : {1u, 2u, 5u}) {
        Options options{op};
        options.threads = threads;
        const auto r = boolean_op<K>(inputs.first, inputs.second, options);
        const Output out = to_output<K, K>(r);
        std::string text = cycles_text(r);
        for (const auto& p : out.polygons) text += "polygon with " + std::to_string(p.holes.size()) + " holes\n";
        seen.push_back(text);
        EXPECT_EQ(seen.front(), text) << name << " " << operation_name(op) << " on " << threads << " threads";
      }
      EXPECT_FALSE(seen.front().empty());
    }
  }
}

// The result cycles of a regular operation through steps 1-6 on `threads`, with step 5
// making runs of fragments one EF entry (`runs`, in cycles of `short_cycle` fragments or
// more) or inserting each fragment; `num_runs` counts the runs made.
std::vector<ResultCycle> cycles_through_ef(const Polygon& a, const Polygon& b, Operation op, bool runs,
                                           unsigned threads, int short_cycle, std::size_t& num_runs) {
  Arrangement<K> arr = prepare<K>(to_kernel_polygon<K>(a), to_kernel_polygon<K>(b), PairSearch::sweep, threads);
  normalize_orientations(arr, op, threads);
  build_vertex_rings(arr);
  insert_intersections(arr, PairSearch::sweep, threads);
  const Incidence inc = classify_fragments(arr, threads);
  HashEdgeTable ef = detail::make_ef_table<HashEdgeTable>(arr);
  if (runs) {
    select_runs_into_hash(arr, inc, op, ef, threads, short_cycle);
  } else {
    select_fragments(arr, inc, op, true, [&](int, const EfEntry& e) { ef.insert(e, true); });
  }
  num_runs += ef.num_runs();
  return construct_result_cycles(arr, ef, op);
}

// Step 5's runs (paper-notes.md, deviation 20) change nothing in the result: the same
// cycles with the same first vertices, directions and types as fragment by fragment, on one
// thread and on two, for every operation (difference keeps B's fragments reversed), on
// inputs with touching rings, shared edges, crossings and holes.
TEST(EfRuns, SameCyclesBitForBitAsFragmentByFragment) {
  std::vector<std::pair<std::string, std::pair<Polygon, Polygon>>> inputs = large_inputs();
  // Long cycles in both polygons, enough for B to be decided on a second thread.
  const int n = static_cast<int>(2 * kParallelWork);
  inputs.push_back({"wavy", {wavy_disc(n, 7, 0, 0), wavy_disc(n, 7, 20, 5)}});
  std::mt19937_64 rng(41);
  add_soups_and_random_pairs(rng, 3, 60, inputs);
  std::size_t runs_made = 0, runs_seen = 0, cycles = 0;
  for (const auto& [name, ab] : inputs) {
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                               Operation::symmetric_difference}) {
      std::size_t none = 0;
      const std::vector<ResultCycle> want = cycles_through_ef(ab.first, ab.second, op, false, 1, 1, none);
      ASSERT_EQ(none, 0u);
      for (const auto& [threads, short_cycle] : {std::pair{1u, 1}, std::pair{2u, 1}, std::pair{2u, kShortCycle}}) {
        std::size_t made = 0;
        const std::vector<ResultCycle> got =
            cycles_through_ef(ab.first, ab.second, op, true, threads, short_cycle, made);
        if (short_cycle == 1) {
          runs_made += made;
          runs_seen += made > 0;
        }
        ASSERT_EQ(got.size(), want.size()) << name << " " << operation_name(op) << " on " << threads << " threads";
        for (std::size_t c = 0; c < want.size(); ++c) {
          EXPECT_EQ(got[c].vertices, want[c].vertices) << name << " " << operation_name(op) << " cycle " << c;
          EXPECT_TRUE(got[c].directions == want[c].directions) << name << " " << operation_name(op) << " cycle " << c;
          EXPECT_EQ(got[c].type, want[c].type) << name << " " << operation_name(op) << " cycle " << c;
          EXPECT_EQ(got[c].counterclockwise, want[c].counterclockwise) << name << " " << operation_name(op);
        }
        cycles += want.size();
      }
    }
  }
  // The runs were there to test: most cases make some when every cycle may have runs
  // (runs_seen counts cases on both thread counts, 8 per input).
  EXPECT_GT(runs_seen, inputs.size() * 4);
  EXPECT_GT(runs_made, 10000u);
  std::cout << runs_made << " runs in " << cycles << " cycles\n";
}

// Step 6 without choices (detail::forced_cycles) on the large inputs, every operation: where
// it makes the cycles, the walk over the same EF makes the same ones in the same order, and
// where some vertex has a choice it makes none. Both happen here.
TEST(ForcedCycles, SameCyclesAsTheWalkWhereNoVertexHasAChoice) {
  int forced = 0, refused = 0;
  for (const auto& [name, ab] : large_inputs()) {
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                               Operation::symmetric_difference}) {
      Arrangement<K> arr = prepare<K>(to_kernel_polygon<K>(ab.first), to_kernel_polygon<K>(ab.second), PairSearch::sweep, 2);
      normalize_orientations(arr, op, 2);
      build_vertex_rings(arr, 2);
      insert_intersections(arr, PairSearch::sweep, 2);
      const Incidence inc = classify_fragments(arr, 2);
      HashEdgeTable ef = detail::make_ef_table<HashEdgeTable>(arr);
      select_runs_into_hash(arr, inc, op, ef, 2);
      const PolygonType ccw_type =
          kTable4[op_index(op)][type_index(arr.polygon[0].type)][type_index(arr.polygon[1].type)];
      std::vector<ResultCycle> got;
      const bool made = detail::forced_cycles(DirectionOrder<K>(arr.points), ef, ccw_type, 2, got);
      const std::vector<ResultCycle> want = construct_result_cycles(arr, ef, op, 1);  // the walk, on one thread
      ASSERT_FALSE(want.empty()) << name << " " << operation_name(op);
      if (!made) {
        ++refused;
        EXPECT_TRUE(got.empty()) << name << " " << operation_name(op);
        continue;
      }
      ++forced;
      ASSERT_EQ(got.size(), want.size()) << name << " " << operation_name(op);
      for (std::size_t c = 0; c < want.size(); ++c) {
        EXPECT_EQ(got[c].vertices, want[c].vertices) << name << " " << operation_name(op) << " cycle " << c;
        EXPECT_TRUE(got[c].directions == want[c].directions) << name << " " << operation_name(op) << " cycle " << c;
        EXPECT_EQ(got[c].type, want[c].type) << name << " " << operation_name(op) << " cycle " << c;
        EXPECT_EQ(got[c].counterclockwise, want[c].counterclockwise) << name << " " << operation_name(op);
      }
    }
  }
  EXPECT_GT(forced, 0);
  EXPECT_GT(refused, 0);
}

// Step 3 with the crossings and touching points the preparation found (one pair search over
// both polygons, kept when nothing was inserted and every ring stayed one cycle) makes the
// same fragments as step 3's own search of the vertex-complete edges: per polygon, fragment
// by fragment, the same edge and the same exact end points, for every operation (step 1
// turns cycles, difference turns B), on one thread and on two. Both paths are taken.
TEST(EarlyIntersections, SameFragmentsAsStepThreesOwnSearch) {
  std::vector<std::pair<std::string, std::pair<Polygon, Polygon>>> inputs = large_inputs();
  std::mt19937_64 rng(43);
  add_soups_and_random_pairs(rng, 2, 40, inputs);
  // Where the preparation's findings are dropped: a vertex on an edge of its own polygon (a
  // point inserted), a ring through one point twice (split into two cycles).
  const Polygon diamond{{{{1, -1}, {4, 1.5}, {1, 4}, {-2, 1.5}}}, PolygonType::island};
  inputs.push_back({"t-junction", {Polygon{{square_ring(0, 0, 2, 2), square_ring(2, 1, 3, 3)}, PolygonType::island}, diamond}});
  inputs.push_back({"pinched", {Polygon{{{{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 1}}}, PolygonType::island}, diamond}});
  inputs.push_back({"t-junction in B", {diamond, Polygon{{square_ring(0, 0, 2, 2), square_ring(2, 1, 3, 3)}, PolygonType::island}}});
  const auto fragments = [](const Arrangement<K>& arr, int g) {
    std::vector<std::string> out;
    for (const Fragment& f : arr.polygon[g].fragments) {
      const auto u = K::exact_coordinates(arr.vertex(f.from));
      const auto w = K::exact_coordinates(arr.vertex(f.to));
      out.push_back(std::to_string(f.edge) + ": " + u[0] + "," + u[1] + " -> " + w[0] + "," + w[1]);
    }
    return out;
  };
  int early = 0, searched = 0;
  for (const auto& [name, ab] : inputs) {
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                               Operation::symmetric_difference}) {
      for (const unsigned threads : {1u, 2u}) {
        Arrangement<K> with = prepare<K>(to_kernel_polygon<K>(ab.first), to_kernel_polygon<K>(ab.second),
                                         PairSearch::sweep, threads);
        Arrangement<K> without = with;
        (with.early.found ? early : searched) += 1;
        without.early = {};
        for (Arrangement<K>* arr : {&with, &without}) {
          normalize_orientations(*arr, op, threads);
          build_vertex_rings(*arr);
          insert_intersections(*arr, PairSearch::sweep, threads);
        }
        EXPECT_EQ(with.num_crossings(), without.num_crossings()) << name;
        for (int g = 0; g < 2; ++g) {
          EXPECT_EQ(fragments(with, g), fragments(without, g)) << name << " " << operation_name(op) << " polygon " << g;
        }
      }
    }
  }
  EXPECT_GT(early, 0);
  EXPECT_GT(searched, 0);
  std::cout << early << " arrangements with the preparation's intersections, " << searched << " without\n";
}

// The sweep that finds a polygon's edges meeting only at shared ends (core/clean_edges.hpp)
// against every pair (or, for large polygons, every candidate pair): the same verdict on
// segment soups, random polygons, the large inputs, and stars of integer points each with a
// second ring placed at a point of one of its edges (shared end, point on an edge, a
// crossing or an overlap, whatever it makes).
TEST(CleanEdges, SweepVerdictIsEveryPairs) {
  std::mt19937_64 rng(47);
  std::vector<Polygon> polygons = segment_soups(rng);
  for (int k = 0; k < 60; ++k) polygons.push_back(random_polygon(rng, false));
  for (const auto& [name, ab] : large_inputs()) {
    polygons.push_back(ab.first);
    polygons.push_back(ab.second);
  }
  for (int k = 0; k < 80; ++k) {
    Ring star = test::random_star(rng, 0, 0, 2, 30 + k, 40 + 4 * k);
    polygons.push_back(Polygon{{star}, PolygonType::island});
    const std::size_t e = rng() % star.size();
    const Point& p = star[e];
    const Point& q = star[(e + 1) % star.size()];
    const Point at = k % 3 == 0 ? p : Point{(p.x + q.x) / 2, (p.y + q.y) / 2};  // exact: integers
    const double dx = q.x - p.x, dy = q.y - p.y;
    Ring other;
    switch (k % 4) {
      case 0: other = {at, {at.x - dy, at.y + dx}, {at.x - dy - dx, at.y + dx - dy}}; break;  // outward
      case 1: other = {at, {at.x + dy, at.y - dx}, {at.x + dy + dx, at.y - dx + dy}}; break;  // inward
      case 2: other = {at, {at.x + dx, at.y + dy}, {at.x + dx - dy, at.y + dy + dx}}; break;   // along the edge
      default: other = {{at.x + 0.25, at.y}, {at.x + 0.25, at.y + 100}, {at.x + 0.5, at.y + 100}}; break;
    }
    polygons.push_back(Polygon{{star, other}, PolygonType::island});
  }
  // Two edges that cross after the ring between them has ended: neighbours only then.
  polygons.push_back(Polygon{{{{0, 1}, {3, 1.1}, {3, 0.9}}, {{1, 0.5}, {10, 2}, {10, -3}}, {{2, 1.8}, {9, 0.3}, {2, 3}}},
                             PolygonType::island});
  int clean = 0, not_clean = 0;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const Items s = items_of(polygons[i], Polygon{});
    const auto meet = [&](int a, int b) {
      const SweepItem& x = s.items[static_cast<std::size_t>(a)];
      const SweepItem& y = s.items[static_cast<std::size_t>(b)];
      if (x.lo == y.lo && x.hi == y.hi) return true;
      const SegmentRelation rel = relate_segments_by_id<K>(s.pts, x.lo, x.hi, y.lo, y.hi);
      return rel.proper_crossing || rel.touches();
    };
    bool expected = true;
    if (s.items.size() <= 3000) {
      for (std::size_t a = 0; a < s.items.size() && expected; ++a) {
        for (std::size_t b = a + 1; b < s.items.size() && expected; ++b) expected = !meet(static_cast<int>(a), static_cast<int>(b));
      }
    } else {
      for_each_candidate_pair<K>(s.pts, s.x_rank, s.items, false, PairSearch::sweep, [&](int a, int b) {
        if (meet(a, b)) expected = false;
      });
    }
    ASSERT_EQ(edges_meet_only_at_ends<K>(s.pts, s.items), expected) << "polygon " << i << ": " << describe(polygons[i]);
    (expected ? clean : not_clean) += 1;
  }
  EXPECT_GT(clean, 60);
  EXPECT_GT(not_clean, 60);
  std::cout << clean << " polygons whose edges meet only at shared ends, " << not_clean << " others\n";
}

// Spiky stars, whose own pairs of edges the preparation leaves to the sweep (checked here:
// many box pairs, edges meeting only at shared ends): the crossings it finds between A and
// B make the same fragments as step 3's own search over the vertex-complete edges, and a
// star made to cross itself is refused with the rational kernel's message (that kernel
// searches every pair of edges).
TEST(CleanEdges, SpikyStarsTheSameFragmentsAndErrorsAsEveryPairSearched) {
  std::mt19937_64 rng(53);
  const Polygon a{{test::random_star(rng, 0, 0, 2, 1000, 2000)}, PolygonType::island};
  const Polygon b{{test::random_star(rng, 300, 100, 2, 1000, 2000)}, PolygonType::island};
  for (const Polygon* p : {&a, &b}) {
    const Items s = items_of(*p, Polygon{});
    ASSERT_GT(estimated_box_pairs<K>(s.pts, s.items), 32.0 * static_cast<double>(s.items.size()));
    ASSERT_TRUE(edges_meet_only_at_ends<K>(s.pts, s.items));
  }
  // A vertex by what defines it exactly: an input point, or the crossing of two segments
  // (each with its ends in order, A's first), which is cheaper to compare than its rational
  // coordinates.
  const auto name = [](const ExactVertex& v) {
    char text[256];
    const auto ordered = [](Point p, Point q) { return p.x < q.x || (p.x == q.x && p.y < q.y) ? std::pair(p, q) : std::pair(q, p); };
    if (!v.is_crossing) {
      std::snprintf(text, sizeof text, "%a %a", v.a0.x, v.a0.y);
    } else {
      const auto [a0, a1] = ordered(v.a0, v.a1);
      const auto [b0, b1] = ordered(v.b0, v.b1);
      std::snprintf(text, sizeof text, "%a %a %a %a x %a %a %a %a", a0.x, a0.y, a1.x, a1.y, b0.x, b0.y, b1.x, b1.y);
    }
    return std::string(text);
  };
  const auto fragments = [&](const Arrangement<K>& arr, int g) {
    std::vector<std::string> out;
    for (const Fragment& f : arr.polygon[g].fragments) {
      out.push_back(std::to_string(f.edge) + ": " + name(arr.vertex(f.from)) + " -> " + name(arr.vertex(f.to)));
    }
    return out;
  };
  for (const unsigned threads : {1u, 2u}) {
    Arrangement<K> with = prepare<K>(to_kernel_polygon<K>(a), to_kernel_polygon<K>(b), PairSearch::sweep, threads);
    ASSERT_TRUE(with.early.found);
    Arrangement<K> without = with;
    without.early = {};
    for (Arrangement<K>* arr : {&with, &without}) {
      normalize_orientations(*arr, Operation::intersection, threads);
      build_vertex_rings(*arr);
      insert_intersections(*arr, PairSearch::sweep, threads);
    }
    EXPECT_EQ(with.num_crossings(), without.num_crossings());
    EXPECT_GT(with.num_crossings(), 10000);
    for (int g = 0; g < 2; ++g) EXPECT_EQ(fragments(with, g), fragments(without, g)) << "polygon " << g;
  }
  Polygon crossed = a;  // two far vertices swapped: edges that cross
  auto& r = crossed.rings[0];
  std::swap(r[3], r[r.size() / 2]);
  std::string exact_error, rational_error;
  try {
    boolean_op<K>(to_kernel_polygon<K>(crossed), to_kernel_polygon<K>(b), Options{});
  } catch (const CrossingEdges& e) {
    exact_error = e.what();
  }
  try {
    boolean_op<RationalKernel>(to_kernel_polygon<RationalKernel>(crossed), to_kernel_polygon<RationalKernel>(b), Options{});
  } catch (const CrossingEdges& e) {
    rational_error = e.what();
  }
  EXPECT_FALSE(exact_error.empty());
  EXPECT_EQ(exact_error, rational_error);
}

// Step 3 gives one id per crossing point even when edges of a polygon that coincide (two
// squares sharing a side, each with its own copy of it) are crossed more than 1024 times,
// beside as many crossings of edges that coincide with none, which take their ids without
// the map (CrossingIds' marks). The expected counts are B's edges that cross the shared
// side or A's bottom side, counted here; the areas are the oracle's, by inclusion and
// exclusion: area(A u B) + area(A n B) = area(A) + area(B).
TEST(CrossingIds, OnePointPerCrossingOfCoincidingEdgesAmongManyCrossings) {
  const Polygon a{{square_ring(0, 0, 100, 1), square_ring(0, 1, 100, 2)}, PolygonType::island};
  Ring upper;  // across the shared side y = 1
  for (int k = 0; k < 1200; ++k) upper.push_back({0.05 + 0.08 * k, k % 2 == 0 ? 0.5 : 1.5});
  upper.push_back({upper.back().x, 0.25});
  upper.push_back({0.05, 0.25});
  Ring lower;  // across A's bottom side y = 0, below the upper ring
  for (int k = 0; k < 1200; ++k) lower.push_back({0.04 + 0.08 * k, k % 2 == 0 ? -0.2 : 0.2});
  lower.push_back({lower.back().x, 0.22});
  lower.push_back({0.04, 0.22});
  const Polygon b{{upper, lower}, PolygonType::island};
  const auto crossing = [](const Ring& r, double y) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < r.size(); ++k) n += (r[k].y < y) != (r[(k + 1) % r.size()].y < y);
    return n;
  };
  const std::size_t expected = crossing(upper, 1) + crossing(lower, 0);
  ASSERT_GT(crossing(upper, 1), 1024u);
  ASSERT_GT(crossing(lower, 0), 1024u);
  const Q sum = area(to_qrings(a)) + area(to_qrings(b));
  for (const unsigned threads : {1u, 2u}) {
    Options options;
    options.threads = threads;
    options.op = Operation::union_;
    const BooleanResult<K> exact = boolean_op<K>(to_kernel_polygon<K>(a), to_kernel_polygon<K>(b), options);
    EXPECT_EQ(exact.stats.crossings, expected) << threads << " threads";
    const BooleanResult<RationalKernel> u =
        boolean_op<RationalKernel>(to_kernel_polygon<RationalKernel>(a), to_kernel_polygon<RationalKernel>(b), options);
    options.op = Operation::intersection;
    const BooleanResult<RationalKernel> i =
        boolean_op<RationalKernel>(to_kernel_polygon<RationalKernel>(a), to_kernel_polygon<RationalKernel>(b), options);
    EXPECT_EQ(u.stats.crossings, expected);
    EXPECT_EQ(i.stats.crossings, expected);
    EXPECT_EQ(area(result_rings(u)) + area(result_rings(i)), sum);
  }
}

// Whether closed segments a b and c d have a point in common, from the signs of four
// orientations (exact) and, for collinear ones, whether their ranges overlap.
bool segments_meet(const std::vector<Point>& p, int a, int b, int c, int d) {
  const Sign o1 = K::orient2d(p[a], p[b], p[c]), o2 = K::orient2d(p[a], p[b], p[d]);
  const Sign o3 = K::orient2d(p[c], p[d], p[a]), o4 = K::orient2d(p[c], p[d], p[b]);
  const auto between = [&](int u, int v, int q) {  // q on the line of u v: within the segment?
    return std::min(p[u].x, p[v].x) <= p[q].x && p[q].x <= std::max(p[u].x, p[v].x) &&
           std::min(p[u].y, p[v].y) <= p[q].y && p[q].y <= std::max(p[u].y, p[v].y);
  };
  if (o1 != Sign::zero && o1 == o2) return false;
  if (o3 != Sign::zero && o3 == o4) return false;
  if (o1 != Sign::zero || o3 != Sign::zero) {
    // Not all collinear: they cross, or an end lies on the other segment.
    if (o1 != Sign::zero && o2 != Sign::zero && o3 != Sign::zero && o4 != Sign::zero) return true;
    return (o1 == Sign::zero && between(a, b, c)) || (o2 == Sign::zero && between(a, b, d)) ||
           (o3 == Sign::zero && between(c, d, a)) || (o4 == Sign::zero && between(c, d, b));
  }
  return between(a, b, c) || between(a, b, d) || between(c, d, a) || between(c, d, b);
}

// Segments of two colours on a small grid (verticals, collinear overlaps, ends on other
// segments, shared ends, crossings at grid points and between them), each colour drawn so
// that its own segments meet only at shared ends, without overlapping.
Items grid_red_blue(std::mt19937_64& rng, int grid, int per_colour) {
  std::uniform_int_distribution<int> coord(0, grid);
  std::vector<std::array<Point, 2>> segs[2];
  for (int g = 0; g < 2; ++g) {
    for (int tries = 0; static_cast<int>(segs[g].size()) < per_colour && tries < 50 * per_colour; ++tries) {
      const Point u{static_cast<double>(coord(rng)), static_cast<double>(coord(rng))};
      const Point w{static_cast<double>(coord(rng)), static_cast<double>(coord(rng))};
      if (u == w) continue;
      bool ok = true;
      for (const auto& t : segs[g]) {
        const std::vector<Point> q{u, w, t[0], t[1]};
        if (!segments_meet(q, 0, 1, 2, 3)) continue;
        // Meeting only at a shared end: one end in common, and the other two not on one ray.
        const int shared = (u == t[0] || u == t[1]) + (w == t[0] || w == t[1]);
        if (shared != 1) {
          ok = false;
          break;
        }
        const Point e = (u == t[0] || u == t[1]) ? u : w;
        const Point s_other = e == u ? w : u;
        const Point t_other = e == t[0] ? t[1] : t[0];
        const bool overlap = K::orient2d(e, s_other, t_other) == Sign::zero &&
                             (s_other.x - e.x) * (t_other.x - e.x) + (s_other.y - e.y) * (t_other.y - e.y) > 0;
        if (overlap) {
          ok = false;
          break;
        }
      }
      if (ok) segs[g].push_back({u, w});
    }
  }
  Items out;
  std::vector<Point> all;
  for (int g = 0; g < 2; ++g) {
    for (const auto& t : segs[g]) all.insert(all.end(), t.begin(), t.end());
  }
  const auto less = [](const Point& u, const Point& w) { return u.x != w.x ? u.x < w.x : u.y < w.y; };
  std::sort(all.begin(), all.end(), less);
  all.erase(std::unique(all.begin(), all.end()), all.end());
  out.pts = all;
  out.x_rank.resize(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) out.x_rank[i] = i == 0 ? 0 : out.x_rank[i - 1] + (all[i].x != all[i - 1].x);
  const auto id = [&](const Point& q) { return static_cast<int>(std::lower_bound(all.begin(), all.end(), q, less) - all.begin()); };
  for (int g = 0; g < 2; ++g) {
    for (const auto& t : segs[g]) out.items.push_back(sweep_item(id(t[0]), id(t[1]), g, false));
  }
  return out;
}

// Whether the items of each group (A's first) meet only at shared ends, as the sweep needs.
bool each_group_clean(const Items& s) {
  const auto na = static_cast<std::size_t>(std::count_if(s.items.begin(), s.items.end(), [](const SweepItem& it) { return it.group == 0; }));
  const std::span<const SweepItem> all(s.items);
  return edges_meet_only_at_ends<K>(s.pts, all.first(na)) && edges_meet_only_at_ends<K>(s.pts, all.subspan(na));
}

// Whether segments a b and c d (point ids, a < b, c < d) have a common point other than an
// end of both: they meet, and unless they share exactly one end they are not the same
// segment; sharing one end e, they overlap from e (collinear, the same way).
bool meet_beyond_shared_end(const std::vector<Point>& p, int a, int b, int c, int d) {
  if (!segments_meet(p, a, b, c, d)) return false;
  const int shared = (a == c || a == d) + (b == c || b == d);
  if (shared == 2) return false;  // the same segment
  if (shared == 0) return true;
  const int e = (a == c || a == d) ? a : b;
  const int u = e == a ? b : a, w = e == c ? d : c;
  return K::orient2d(p[e], p[u], p[w]) == Sign::zero &&
         (p[u].x - p[e].x) * (p[w].x - p[e].x) + (p[u].y - p[e].y) * (p[w].y - p[e].y) > 0;
}

// The sweep's pairs against every red-blue pair with a common point other than an end of
// both, found pair by pair.
void expect_meeting_pairs(const Items& s, const std::string& name) {
  const auto found = red_blue_meeting_pairs<K>(s.pts, s.items);
  std::vector<std::pair<int, int>> expected;
  for (int a = 0; a < static_cast<int>(s.items.size()); ++a) {
    for (int b = a + 1; b < static_cast<int>(s.items.size()); ++b) {
      const SweepItem& x = s.items[a];
      const SweepItem& y = s.items[b];
      if (x.group != y.group && meet_beyond_shared_end(s.pts, x.lo, x.hi, y.lo, y.hi)) expected.emplace_back(a, b);
    }
  }
  EXPECT_EQ(found, expected) << name;
}

TEST(RedBlueSweep, FindsEveryPairThatMeetsAndNoOtherOnAGrid) {
  const std::uint64_t seed = 20261129;
  std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  int pairs = 0;
  for (int round = 0; round < 400; ++round) {
    const int grid = 3 + round % 6;
    const Items s = grid_red_blue(rng, grid, 4 + round % 25);
    ASSERT_TRUE(each_group_clean(s)) << "round " << round;
    expect_meeting_pairs(s, "grid round " + std::to_string(round));
    pairs += static_cast<int>(red_blue_meeting_pairs<K>(s.pts, s.items).size());
  }
  EXPECT_GT(pairs, 4000);  // the rounds meet in many ways, not a few
}

TEST(RedBlueSweep, FindsEveryPairThatMeetsBetweenRings) {
  const std::vector<Polygon> soups = soups_from(20261130);
  int checked = 0;
  for (std::size_t i = 0; i < soups.size(); ++i) {
    for (std::size_t j = 0; j < soups.size(); ++j) {
      const Items s = items_of(soups[i], soups[j]);
      if (!each_group_clean(s)) continue;
      expect_meeting_pairs(s, "soups " + std::to_string(i) + " " + std::to_string(j));
      ++checked;
    }
  }
  const Items wavy = items_of(nested_wavy_rings(12, 24, 0, 0, 0), nested_wavy_rings(12, 24, 0.7, 0.3, 1));
  expect_meeting_pairs(wavy, "nested wavy rings");
  EXPECT_GT(checked, 20);
}

TEST(CandidatePairs, ABudgetOfMergesStopsTheSearchAndSaysSo) {
  const Items s = items_of(nested_wavy_rings(60, 32, 0, 0, 0), nested_wavy_rings(60, 32, 0.7, 0.3, 1));
  const auto run = [&](std::int64_t merges, std::size_t& count) {
    CandidatePairs<K> pairs(s.pts, s.x_rank, s.items, true, PairSearch::sweep, 2);
    if (merges >= 0) pairs.limit_merges(merges);
    count = 0;
    for (std::size_t part = 0; part < pairs.parts(); ++part) pairs.for_each_in_part(part, [&](int, int) { ++count; });
    return pairs.exhausted();
  };
  std::size_t all = 0, some = 0, within = 0;
  EXPECT_FALSE(run(-1, all));
  EXPECT_TRUE(run(4096, some));
  EXPECT_LT(some, all);
  EXPECT_FALSE(run(std::int64_t{1} << 40, within));
  EXPECT_EQ(within, all);
}

// The operation with the preparation's pairs from the sweep over both polygons against the
// paper's every-pair search: the same result cycles, vertex by vertex, exactly.
TEST(RedBlueSweep, OperationAgreesWithEveryPairSearch) {
  std::mt19937_64 rng(20261131);
  std::vector<std::pair<Polygon, Polygon>> cases;
  const std::vector<Polygon> soups = segment_soups(rng);
  for (std::size_t i = 0; i < soups.size(); ++i) cases.push_back({soups[i], soups[(i + 3) % soups.size()]});
  for (int k = 0; k < 20; ++k) cases.push_back({random_polygon(rng, true), random_polygon(rng, true)});
  cases.push_back({nested_wavy_rings(10, 20, 0, 0, 0), nested_wavy_rings(10, 20, 0.7, 0.3, 1)});
  cases.push_back({nested_wavy_rings(10, 20, 0, 0, 0), nested_wavy_rings(10, 20, 0, 0, 0)});  // the same rings
  // Fans: triangles of both polygons meeting at one apex (parts touching at a point), some
  // sides of B on sides of A.
  const auto fan = [](int n, double turn, double radius) {
    Polygon f;
    for (int i = 0; i < n; ++i) {
      const double t0 = 2 * std::numbers::pi * (i + turn) / n, t1 = 2 * std::numbers::pi * (i + turn + 0.5) / n;
      f.rings.push_back({{0, 0}, {radius * std::cos(t0), radius * std::sin(t0)}, {radius * std::cos(t1), radius * std::sin(t1)}});
    }
    return f;
  };
  cases.push_back({fan(24, 0, 8), fan(24, 0.25, 6)});
  cases.push_back({fan(24, 0, 8), fan(24, 0, 6)});
  // Flowers: one ring through the apex again and again, split into cycles there, so that
  // step 3 searches again instead of taking the preparation's findings.
  const auto flower = [&](int n, double turn, double radius) {
    Polygon f;
    f.rings.emplace_back();
    for (const Ring& petal : fan(n, turn, radius).rings) f.rings[0].insert(f.rings[0].end(), petal.begin(), petal.end());
    return f;
  };
  cases.push_back({flower(24, 0, 8), flower(24, 0.25, 6)});
  cases.push_back({flower(24, 0, 8), fan(24, 0.25, 6)});
  cases.push_back({flower(24, 0, 8), flower(24, 0, 6)});
  int compared = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference, Operation::symmetric_difference}) {
      const auto a = to_kernel_polygon<K>(cases[c].first), b = to_kernel_polygon<K>(cases[c].second);
      const auto every = boolean_op<K>(a, b, Options{op, true, EfOrganisation::hash, PairSearch::all_pairs});
      const auto swept = boolean_op<K>(a, b, Options{op, true, EfOrganisation::hash, PairSearch::red_blue});
      EXPECT_EQ(cycles_text(every), cycles_text(swept)) << "case " << c << " " << operation_name(op);
      compared += !every.cycles.empty();
    }
  }
  EXPECT_GT(compared, 80);
}

}  // namespace
}  // namespace mk::test
