// Turns a kernel's result into the kernel-independent Output: irreducible polygons with
// types, OGC polygons-with-holes through the inclusion forest, non-regular parts, and
// whether the coordinates rounded to the nearest doubles still form a valid output (OGC
// validity, as GEOS's isValid defines it, decided exactly).
// [MK89 §2.2] (inclusion forest) [MK89 §3.3] (detecting non-orientable rounded output)
// [OGC06-103 §6.1.11]
// Preconditions: `result` comes from boolean_op with kernel K; V is an exact kernel over
// doubles (its Point constructible from mk::Point) used to check the rounded output. For
// exact kernels the exact result is valid (the certificate of rounding_motion.hpp relies on
// it; tests/core/ogc_validity_test.cpp checks it on the degenerate generators).
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/assemble.hpp"
#include "core/boolean_op.hpp"
#include "core/ogc_validity.hpp"
#include "core/output.hpp"
#include "core/parallel.hpp"
#include "core/rounded_rings.hpp"
#include "core/rounding_boxes.hpp"
#include "core/rounding_motion.hpp"

namespace mk {

namespace detail {

// The rounded points of a result's vertices, distinct and in lexicographic order, and each
// vertex id's index among them (-1 for vertices on no cycle). Input points keep their
// lexicographic ids (prepare numbers them so) and round to themselves when they are doubles:
// only the crossings need sorting, and a merge puts every point in order.
template <Kernel K>
void rounded_points_in_order(const BooleanResult<K>& r, const std::vector<std::vector<Point>>& rounded, std::vector<Point>& pts,
                             std::vector<int>& slot) {
  const int num_points = r.arrangement.num_points();
  slot.assign(static_cast<std::size_t>(r.arrangement.num_vertices()), -1);
  std::vector<std::pair<int, Point>> collected, crossings;  // (id, rounded point)
  for (std::size_t c = 0; c < r.cycles.size(); ++c) {
    for (std::size_t k = 0; k < r.cycles[c].vertices.size(); ++k) {
      const int id = r.cycles[c].vertices[k];
      if (slot[static_cast<std::size_t>(id)] >= 0) continue;
      if (id < num_points) {
        slot[static_cast<std::size_t>(id)] = static_cast<int>(collected.size());
        collected.push_back({id, rounded[c][k]});
      } else {
        slot[static_cast<std::size_t>(id)] = 0;
        crossings.push_back({id, rounded[c][k]});
      }
    }
  }
  std::vector<std::pair<int, Point>> inputs;
  inputs.reserve(collected.size());
  for (int id = 0; id < num_points; ++id) {
    if (slot[static_cast<std::size_t>(id)] >= 0) inputs.push_back(collected[static_cast<std::size_t>(slot[static_cast<std::size_t>(id)])]);
  }
  collected = {};
  for (std::size_t k = 1; k < inputs.size(); ++k) {
    if (lexicographically_less(inputs[k].second, inputs[k - 1].second)) {  // exact rational input moved
      crossings.insert(crossings.end(), inputs.begin(), inputs.end());
      inputs.clear();
      break;
    }
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const auto& a, const auto& b) { return lexicographically_less(a.second, b.second); });
  pts.clear();
  pts.reserve(inputs.size() + crossings.size());
  std::size_t i = 0, j = 0;
  while (i < inputs.size() || j < crossings.size()) {
    const bool take_input =
        j == crossings.size() || (i < inputs.size() && !lexicographically_less(crossings[j].second, inputs[i].second));
    const auto& [id, p] = take_input ? inputs[i++] : crossings[j++];
    if (pts.empty() || !(pts.back() == p)) pts.push_back(p);
    slot[static_cast<std::size_t>(id)] = static_cast<int>(pts.size()) - 1;
  }
}

// Every cycle's vertices rounded to the nearest doubles. A kernel whose vertices are plain
// values (VertexBoxes: no shared lazy state) rounds a large result on several threads, in
// equal runs of the cycles' vertices one after another: the same doubles on any number.
// With `halves` (VertexBoxes kernels), also each vertex's box half-sizes for the rounding
// certificate, while the vertex is at hand.
template <Kernel K>
std::vector<std::vector<Point>> rounded_cycles(const BooleanResult<K>& r, unsigned threads, RoundingHalves* halves = nullptr) {
  std::vector<std::vector<Point>> rounded(r.cycles.size());
  std::vector<std::size_t> first{0};  // the cycles' vertices numbered one after another
  if constexpr (!VertexBoxes<K>) halves = nullptr;
  first.reserve(r.cycles.size() + 1);
  for (std::size_t c = 0; c < r.cycles.size(); ++c) first.push_back(first.back() + r.cycles[c].vertices.size());
  const std::size_t work = first.back();
  const unsigned t = VertexBoxes<K> ? threads_for(work, threads) : 1;
  const std::size_t parts = t > 1 ? 8 * static_cast<std::size_t>(t) : 1;
  // The cycles' vectors, made on the threads too (many small cycles: star 1e4 has 60,737).
  run_tasks(t, parts, [&](std::size_t part) {
    const std::size_t lo = r.cycles.size() * part / parts, hi = r.cycles.size() * (part + 1) / parts;
    for (std::size_t c = lo; c < hi; ++c) rounded[c].resize(r.cycles[c].vertices.size());
  });
  if (halves) {
    halves->first = first;
    halves->sizes.resize(work);
  }
  // Each part walks its run of vertices, calling at(id, out, i) for each (its id, where its
  // rounding goes and its number across the cycles), and asks for the vertex `ahead` places
  // on to be fetched: in cycle order the crossings are scattered over the arrangement's
  // array, and once rounding got fast (the extended-precision stage of
  // crossing_rounding.hpp) waiting for them was most of its time (star 1e4, one thread:
  // 21 ms to 14 ms). The walk goes a cycle at a time with its arrays at hand.
  constexpr std::size_t ahead = 16;
  const auto walk = [&](auto&& at) {
    run_tasks(t, parts, [&](std::size_t part) {
      const std::size_t lo = work * part / parts, hi = work * (part + 1) / parts;
      if (lo >= hi) return;  // (no cycle may hold vertex lo)
      std::size_t c = static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), lo) - first.begin()) - 1;
      // The cycle of the vertex `ahead` places on, its ids and the numbers it spans.
      std::size_t c_ahead = c;
      const int* ids_ahead = r.cycles[c].vertices.data();
      std::size_t from_ahead = first[c], to_ahead = first[c + 1];
      for (std::size_t i = lo; i < hi; ++c) {
        const int* ids = r.cycles[c].vertices.data();
        Point* out = rounded[c].data();
        const std::size_t from = first[c], to = std::min(hi, first[c + 1]);
        for (; i < to; ++i) {
          if (i + ahead < hi) {
            while (i + ahead >= to_ahead) {
              ++c_ahead;
              ids_ahead = r.cycles[c_ahead].vertices.data();
              from_ahead = to_ahead;
              to_ahead = first[c_ahead + 1];
            }
            r.arrangement.prefetch(ids_ahead[i + ahead - from_ahead]);
          }
          at(ids[i - from], out[i - from], i);
        }
      }
    });
  };
  if constexpr (VertexBoxes<K>) {
    if (halves) {
      walk([&](int id, Point& out, std::size_t i) {
        const auto v = r.vertex(id);
        out = K::approx(v);
        halves->sizes[i] = rounding_half_sizes(r, id, v, out);
      });
      return rounded;
    }
  }
  // Input points of doubles are copied from where they are stored: through the vertex made
  // of one and its approximation the compiler (GCC 12) stored the point's halves apart and
  // loaded them as one, a stall that was most of blob 1e5's rounding.
  walk([&](int id, Point& out, std::size_t) {
    if constexpr (std::is_same_v<typename K::Point, Point>) {
      if (r.arrangement.is_input_point(id)) {
        out = r.arrangement.points[static_cast<std::size_t>(id)];
        return;
      }
    }
    out = K::approx(r.vertex(id));
  });
  return rounded;
}

// A rounded cycle as a polygon's ring is written: without the repeated points rounding made
// (exact vertices an ulp apart that round to one double), which GEOS and Clipper never
// write and CGAL's Polygon_2 refuses as not simple; the validity check judges the ring so
// (is_valid_rounded_result_ogc). A ring that would keep fewer than three points is left as
// it is (nearest rounding's invalid output, written as computed).
inline std::vector<Point> without_repeats(const std::vector<Point>& ring) {
  // Almost always none: found by one pass without a branch per point, the ring then copied
  // whole.
  bool repeats = ring.size() > 1 && ring.back() == ring.front();
  for (std::size_t i = 1; i < ring.size(); ++i) repeats |= ring[i] == ring[i - 1];
  if (!repeats) return ring;
  std::vector<Point> out = ring;
  remove_repeated_points(out);
  return out.size() < 3 ? ring : out;
}

}  // namespace detail

// Whether rounding should make the boxes' half-sizes as it goes: when the result has more
// crossings than the exact certificate takes, the box certificate may be asked for them;
// not when step 3 proved its rules (the certificate from them needs no boxes; should it
// refuse, the box certificate makes them itself).
template <Kernel K>
bool rounding_wants_halves(const BooleanResult<K>& r) {
  return static_cast<std::size_t>(r.arrangement.num_crossings()) > kFewCrossingsForExactCertificate &&
         !(r.arrangement.separation.threshold > 0);
}

// Whether the result's polygons (each a list of cycle indices: shell, then holes), with
// their vertices rounded as given, are valid OGC polygons, and its two-sided parts keep two
// distinct ends. For an exact kernel, first the certificates that rounding moved nothing
// across anything: from boxes in floating point (rounding_boxes.hpp: linear, decides
// almost every result of well-separated vertices), then exactly (rounding_motion.hpp: cheap
// when few vertices moved); otherwise one sweep over the rounded output, O(n log n).
// `rounded`: each vertex's nearest doubles, as rounded_cycles makes them (the certificate
// from step 3's rules takes each rounded point to lie in its crossing's box).
template <Kernel K, Kernel V>
bool is_valid_rounded_result_ogc(const BooleanResult<K>& r, const std::vector<std::vector<Point>>& rounded,
                                 const std::vector<std::vector<int>>& polygon_cycles, unsigned threads = 1,
                                 const RoundingHalves* halves = nullptr) {
  for (std::size_t c = 0; c < r.cycles.size(); ++c) {
    if (r.cycles[c].vertices.size() == 2 && rounded[c][0] == rounded[c][1]) return false;
  }
  if constexpr (K::is_exact) {
    // When step 3 proved its rules, the input's rule is all that is left (separation_rules.hpp).
    if constexpr (VertexBoxes<K>) {
      if (rounding_rules_keep_topology(r, threads)) return true;
    }
    // Few crossings: the exact certificate looks near them only; many: the boxes' grid.
    constexpr std::size_t few = kFewCrossingsForExactCertificate;
    std::size_t crossings = static_cast<std::size_t>(r.arrangement.num_crossings());  // those on cycles, at most
    if (crossings > few) {
      crossings = 0;
      for (const auto& c : r.cycles) {
        for (const int id : c.vertices) crossings += !r.arrangement.is_input_point(id);
      }
    }
    const bool few_moved = crossings <= few && std::is_same_v<typename K::Point, Point>;
    if (few_moved && rounding_keeps_topology(r, rounded, few, threads)) return true;
    if constexpr (VertexBoxes<K>) {
      if (rounding_boxes_keep_topology(r, rounded, polygon_cycles, threads, halves)) return true;
    }
    if (!few_moved && rounding_keeps_topology(r, rounded, few, threads)) return true;
  }
  std::vector<Point> pts;
  std::vector<int> slot;
  detail::rounded_points_in_order(r, rounded, pts, slot);
  std::vector<std::vector<int>> rings;
  std::vector<int> part, index_in_part;
  for (std::size_t k = 0; k < polygon_cycles.size(); ++k) {
    for (std::size_t h = 0; h < polygon_cycles[k].size(); ++h) {
      std::vector<int> ring;
      for (const int id : r.cycles[static_cast<std::size_t>(polygon_cycles[k][h])].vertices) {
        const int s = slot[static_cast<std::size_t>(id)];
        if (ring.empty() || ring.back() != s) ring.push_back(s);
      }
      while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
      if (ring.size() < 3) return false;
      rings.push_back(std::move(ring));
      part.push_back(static_cast<int>(k));
      index_in_part.push_back(static_cast<int>(h));
    }
  }
  if constexpr (std::is_same_v<typename V::Point, Point>) {
    return check_indexed_rings<V>(pts, rings, part, index_in_part).defect == OgcDefect::none;
  } else {
    std::vector<typename V::Point> vp;
    vp.reserve(pts.size());
    for (const Point& p : pts) vp.push_back(V::point(p));
    return check_indexed_rings<V>(vp, rings, part, index_in_part).defect == OgcDefect::none;
  }
}

// The polygons of a bounded result, each as its shell's cycle index, then its holes'
// (holes by the inclusion forest); none for an unbounded result.
template <Kernel K>
std::vector<std::vector<int>> result_polygon_cycles(const BooleanResult<K>& r) {
  std::vector<std::vector<int>> polygon_cycles;
  if (r.unbounded) return polygon_cycles;
  const std::vector<int> parent = inclusion_parents(r.arrangement, r.cycles);
  std::vector<int> shell_of(r.cycles.size(), -1);
  for (std::size_t i = 0; i < r.cycles.size(); ++i) {
    if (r.cycles[i].vertices.size() < 3 || r.cycles[i].type != PolygonType::island) continue;
    shell_of[i] = static_cast<int>(polygon_cycles.size());
    polygon_cycles.push_back({static_cast<int>(i)});
  }
  for (std::size_t i = 0; i < r.cycles.size(); ++i) {
    if (r.cycles[i].vertices.size() < 3 || r.cycles[i].type != PolygonType::hole) continue;
    if (parent[i] >= 0 && shell_of[static_cast<std::size_t>(parent[i])] >= 0) {
      polygon_cycles[static_cast<std::size_t>(shell_of[static_cast<std::size_t>(parent[i])])].push_back(static_cast<int>(i));
    }
  }
  return polygon_cycles;
}

// `exact_coordinates`: also write each vertex's exact coordinates as strings (exact kernels),
// which costs more than rounding them. `threads`: for the validity check of large outputs.
template <Kernel K, Kernel V>
Output to_output(const BooleanResult<K>& r, bool exact_coordinates = true, unsigned threads = 1) {
  Output out;
  out.unbounded = r.unbounded;
  // The boxes' half-sizes are made while rounding when the box certificate may be asked.
  RoundingHalves halves;
  const bool many_crossings = rounding_wants_halves(r);
  std::vector<std::vector<Point>> rounded = detail::rounded_cycles(r, threads, many_crossings ? &halves : nullptr);
  const std::vector<std::vector<int>> polygon_cycles = result_polygon_cycles(r);
  // The polygons copy the rounded cycles while the validity check reads them, on a thread of
  // their own for a large output (the check of a result with few crossings runs on one);
  // then the cycles move into `irreducible` (a copy of every vertex less: fresh pages cost
  // more than copying).
  std::size_t vertices = 0;
  for (const auto& c : rounded) vertices += c.size();
  const auto copy_polygons = [&] {
    if (r.unbounded) return;
    out.polygons.reserve(polygon_cycles.size());
    for (const auto& cycles : polygon_cycles) {
      OgcPolygon p{detail::without_repeats(rounded[static_cast<std::size_t>(cycles[0])]), {}};
      p.holes.reserve(cycles.size() - 1);
      for (std::size_t h = 1; h < cycles.size(); ++h) p.holes.push_back(detail::without_repeats(rounded[static_cast<std::size_t>(cycles[h])]));
      out.polygons.push_back(std::move(p));
    }
  };
  run_tasks(threads_for(vertices, threads) > 1 ? 2 : 1, 2, [&](std::size_t task) {
    if (task == 0) {
      out.rounded_valid =
          is_valid_rounded_result_ogc<K, V>(r, rounded, polygon_cycles, threads, many_crossings ? &halves : nullptr);
    } else {
      copy_polygons();
    }
  });
  out.irreducible.resize(r.cycles.size());
  for (std::size_t i = 0; i < r.cycles.size(); ++i) {
    const auto& c = r.cycles[i];
    OutputIrreducible& o = out.irreducible[i];
    o.type = c.type;
    o.vertices = std::move(rounded[i]);
    if (K::is_exact && exact_coordinates) {
      o.exact.reserve(2 * c.vertices.size());
      for (const int id : c.vertices) {
        const auto e = K::exact_coordinates(r.vertex(id));
        o.exact.push_back(e[0]);
        o.exact.push_back(e[1]);
      }
    }
    if (c.vertices.size() == 1) out.isolated_points.push_back(o.vertices[0]);
    if (c.vertices.size() == 2) out.dangling_edges.push_back({o.vertices[0], o.vertices[1]});
  }
  return out;
}

}  // namespace mk
