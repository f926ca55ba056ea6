// Vertices of very high degree (a fan: thousands of parts of both polygons meeting at one
// apex). Steps 1 and 4 to 6 index such a vertex instead of scanning its edges at each visit
// (paper-notes.md, deviation 24): each index must answer exactly what the scan answers.
// Here every index is checked against the scan it replaces, written out in the test, on
// fans whose apex holds hundreds of fragment ends; tests/oracle's "fans" family checks
// whole operations on such inputs against CGAL and the membership oracle.
// [MK89 §4.3] [MK89 §3.3] [MK89 §3.1 step 6]
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/boolean_op.hpp"
#include "core/step1_orientation.hpp"

namespace mk::test {
namespace {

using K = ExactKernel;

// n thin triangles from the origin, the i-th over angles (i + turn) and (i + turn + width)
// steps of 2 pi / n at radius r; width 1 makes neighbours share an edge.
Polygon fan(int n, double turn, double width, double r) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double a0 = 2 * std::numbers::pi * (i + turn) / n;
    const double a1 = width == 1 ? 2 * std::numbers::pi * (i + 1 + turn) / n : 2 * std::numbers::pi * (i + turn + width) / n;
    p.rings.push_back({{0, 0}, {r * std::cos(a0), r * std::sin(a0)}, {r * std::cos(a1), r * std::sin(a1)}});
  }
  return p;
}

std::vector<std::pair<std::string, std::pair<Polygon, Polygon>>> fans() {
  return {{"apart", {fan(150, 0, 0.6, 100), fan(150, 0.3, 0.6, 90)}},
          {"sharing edges", {fan(120, 0, 1, 100), fan(90, 0.5, 1, 70)}},
          {"the same fan", {fan(100, 0, 0.5, 100), fan(100, 0, 0.5, 100)}},
          {"one inside the other", {fan(128, 0, 0.7, 100), fan(64, 0.1, 0.2, 50)}}};
}

// Steps 1 to 4 of `op` on a and b.
Arrangement<K> classified(const Polygon& a, const Polygon& b, Operation op, Incidence& inc) {
  Arrangement<K> arr = prepare<K>(to_kernel_polygon<K>(a), to_kernel_polygon<K>(b), PairSearch::sweep, 1);
  normalize_orientations(arr, op, 1);
  build_vertex_rings(arr);
  insert_intersections(arr, PairSearch::sweep, 1);
  inc = classify_fragments(arr, 1);
  return arr;
}

// Step 4's sums at an indexed vertex: for directions `first` and `last` (those of the ends
// there, their reverses, and others), the sum of the signs of the ends strictly inside the
// counterclockwise sweep, as the Sector test of each end gives it; and step 5's counts of
// fragments along u -> w, as the scan of u's ends gives them.
TEST(HighDegree, SectorSumsAndFragmentsAlongEqualTheScan) {
  std::mt19937_64 rng(41);
  int indexed = 0;
  for (const auto& [name, ab] : fans()) {
    Incidence inc;
    const Arrangement<K> arr = classified(ab.first, ab.second, Operation::intersection, inc);
    const DirectionOrder<K> order(arr.points);
    for (int xi = 0; xi < 2; ++xi) {
      const FragmentEndTable& ends = inc.ends[xi];
      const PreparedPolygon& x = arr.polygon[xi];
      ASSERT_TRUE(ends.by_angle_ready());
      for (int v = 0; v < arr.num_vertices(); ++v) {
        const int m = ends.many(v);
        if (m < 0) continue;
        ++indexed;
        std::vector<Direction> dirs;
        std::set<int> far;
        for (const FragmentEnd& end : ends.at(v)) {
          dirs.push_back(end.dir());
          dirs.push_back(end.dir().reversed());
          const Fragment& f = x.fragments[end.fragment()];
          far.insert(end.sign() > 0 ? f.to : f.from);
        }
        for (const Edge& e : arr.polygon[1 - xi].edges) dirs.push_back({e.src, e.dst});
        std::uniform_int_distribution<std::size_t> pick(0, dirs.size() - 1);
        for (int trial = 0; trial < 400; ++trial) {
          const Direction first = dirs[pick(rng)];
          const Direction last = trial % 8 == 0 ? first : (trial % 8 == 1 ? first.reversed() : dirs[pick(rng)]);
          const typename DirectionOrder<K>::Sector sector(order, first, last);
          int want = 0;
          for (const FragmentEnd& end : ends.at(v)) want += sector.contains(end.dir()) ? end.sign() : 0;
          ASSERT_EQ(ends.signs_in_sweep(order, m, first, last), want) << name << " polygon " << xi << " vertex " << v;
        }
        far.insert(v == 0 ? 1 : 0);  // most likely no neighbour
        for (const int w : far) {
          int same = 0, opposite = 0;
          for (const FragmentEnd& end : ends.at(v)) {
            const Fragment& f = x.fragments[end.fragment()];
            same += end.sign() > 0 && f.to == w;
            opposite += end.sign() < 0 && f.from == w;
          }
          EXPECT_EQ(fragments_along(x, ends, v, w), std::make_pair(same, opposite)) << name << " " << v << " -> " << w;
        }
      }
    }
  }
  EXPECT_GE(indexed, 8);  // the apex of each polygon in each input
}

// Step 6's choice at a vertex with a long chain in EF, as construct_result_cycles's scan of
// every live entry makes it: the entry opposite the arrival first (a two-sided part), else
// the first met turning from it towards the result region.
EfEntry* scanned_choice(const DirectionOrder<K>& order, HashEdgeTable& ef, int v, Direction back, bool result_on_left) {
  EfEntry* best = nullptr;
  ef.for_each_from(v, [&](EfEntry& e) {
    if (best == nullptr) {
      best = &e;
    } else if (order.compare(best->dir, back) != Sign::zero) {
      const bool e_first = order.compare(e.dir, back) == Sign::zero ||
                           (result_on_left ? !order.is_in_ccw_sector(back, best->dir, e.dir)
                                           : order.is_in_ccw_sector(back, best->dir, e.dir));
      if (e_first) best = &e;
    }
  });
  return best;
}

TEST(HighDegree, AngularChoicesEqualTheScanAsEntriesDie) {
  std::mt19937_64 rng(43);
  int long_chains = 0;
  for (const auto& [name, ab] : fans()) {
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::symmetric_difference}) {
      for (const bool on_left : {true, false}) {
        Incidence inc;
        const Arrangement<K> arr = classified(ab.first, ab.second, op, inc);
        const DirectionOrder<K> order(arr.points);
        HashEdgeTable ef = detail::make_ef_table<HashEdgeTable>(arr);
        select_runs_into_hash(arr, inc, op, ef, 1);
        detail::AngularChoices<K> choices(order, ef, on_left);
        std::vector<Direction> dirs;
        for (const auto& p : arr.polygon) {
          for (const Edge& e : p.edges) dirs.push_back({e.src, e.dst});
        }
        for (int v = 0; v < arr.num_vertices(); ++v) {
          if (!ef.is_long(v)) continue;
          ++long_chains;
          for (int step = 0;; ++step) {
            std::vector<EfEntry*> alive;
            ef.for_each_from(v, [&](EfEntry& e) { alive.push_back(&e); });
            // Arrivals: opposite a live entry (a two-sided part), along one, or from anywhere.
            Direction back = dirs[std::uniform_int_distribution<std::size_t>(0, dirs.size() - 1)(rng)];
            if (!alive.empty() && step % 3 != 2) {
              const Direction d = alive[std::uniform_int_distribution<std::size_t>(0, alive.size() - 1)(rng)]->dir;
              back = step % 3 == 0 ? d : d.reversed();
            }
            EfEntry* want = scanned_choice(order, ef, v, back, on_left);
            ASSERT_EQ(choices.choose(v, back), want) << name << " " << operation_name(op) << " vertex " << v << " step " << step;
            if (want == nullptr) break;
            want->alive = false;
            if (alive.size() > 2 && step % 4 == 0) alive[alive.size() / 2]->alive = false;  // dies elsewhere
          }
        }
      }
    }
  }
  EXPECT_GE(long_chains, 12);
}

// InsertEF with long chains: duplicates dropped and opposites cancelled as the scan of a
// chain does it (a model written out here), the entries in the same order from each vertex.
TEST(HighDegree, LongChainsInEfKeepInsertEfsMeaning) {
  std::mt19937_64 rng(47);
  for (const bool regular : {true, false}) {
    constexpr int kVertices = 300;
    HashEdgeTable ef(0, kVertices);
    struct Model {
      int from, to;
      bool alive;
    };
    std::vector<Model> model;
    std::uniform_int_distribution<int> any(1, kVertices - 1);
    for (int i = 0; i < 6000; ++i) {
      // Most entries at or to the hub 0 (its chain grows long), some elsewhere.
      const int u = i % 5 == 4 ? any(rng) % 12 : 0;
      int w = any(rng) % 150;
      if (w == u) w = u + 1;
      const bool reversed = i % 3 == 0;
      const EfEntry e{reversed ? w : u, reversed ? u : w, {reversed ? w : u, reversed ? u : w}, true};
      ef.insert(e, regular);
      bool dropped = false;
      for (const Model& m : model) dropped = dropped || (m.alive && m.from == e.from && m.to == e.to);
      if (!dropped && regular) {
        for (Model& m : model) {
          if (m.alive && m.from == e.to && m.to == e.from) {
            m.alive = false;
            dropped = true;
            break;
          }
        }
      }
      if (!dropped) model.push_back({e.from, e.to, true});
    }
    EXPECT_TRUE(ef.is_long(0));
    for (int v = 0; v < kVertices; ++v) {
      std::vector<std::pair<int, int>> got, want;
      ef.for_each_from(v, [&](EfEntry& e) { got.emplace_back(e.from, e.to); });
      for (const Model& m : model) {
        if (m.alive && m.from == v) want.emplace_back(m.from, m.to);
      }
      ASSERT_EQ(got, want) << "from " << v << (regular ? " regular" : " non-regular");
    }
  }
}

// Step 1's counts of coinciding edges, chained from the end of smaller degree, against a map.
TEST(HighDegree, EdgeCountsFromTheEndOfSmallerDegreeEqualAMap) {
  std::mt19937_64 rng(53);
  std::vector<std::vector<int>> cycles;
  std::uniform_int_distribution<int> any(1, 199);
  for (int c = 0; c < 400; ++c) {  // triangles around the hub 0, some repeated or reversed
    const int a = any(rng), b = any(rng);
    if (a == b) continue;
    cycles.push_back(c % 3 == 0 ? std::vector<int>{b, a, 0} : std::vector<int>{0, a, b});
  }
  detail::EdgeCounts counts(200, cycles);
  std::map<std::pair<int, int>, int> want;
  for (const auto& cycle : cycles) {
    for (std::size_t i = 0; i < cycle.size(); ++i) {
      const int u = cycle[i], w = cycle[(i + 1) % cycle.size()];
      counts.add(u, w);
      ++want[{std::min(u, w), std::max(u, w)}];
    }
  }
  for (int u = 0; u < 200; ++u) {
    for (int w = 0; w < 200; ++w) {
      const auto it = want.find({std::min(u, w), std::max(u, w)});
      ASSERT_EQ(counts.count(u, w), it == want.end() ? 0 : it->second) << u << " " << w;
    }
  }
}

}  // namespace
}  // namespace mk::test
