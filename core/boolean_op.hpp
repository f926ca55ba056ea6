// The Boolean operation: the six steps of the paper in order, with a trace hook between them.
// [MK89 §3.1] [MK89 §3.2] (procedure polygonoperation)
// Preconditions: coordinates finite (checked); everything else about the input is checked
// in prepare(), which names the offending edges.
#pragma once

#include <chrono>
#include <functional>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/arrangement.hpp"
#include "core/edge_fragment_table.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/prepare.hpp"
#include "core/step1_orientation.hpp"
#include "core/step2_vertex_rings.hpp"
#include "core/step3_intersections.hpp"
#include "core/step4_classify.hpp"
#include "core/step5_select.hpp"
#include "core/step6_construct.hpp"

namespace mk {

enum class Step : unsigned char { prepared, oriented, vertex_rings, intersections, classified, selected, constructed };

struct Options {
  Operation op = Operation::intersection;
  bool regular = true;
  EfOrganisation ef = EfOrganisation::hash;
  PairSearch pair_search = PairSearch::sweep;
  // Threads for the phases that run in parallel; 0: every core. The result is the same,
  // bit for bit, on any number of threads.
  unsigned threads = 0;
  // Step 3 proves the rules of the rounding certificate where they apply
  // (separation_rules.hpp); off, the output's grid of boxes decides alone. The result is
  // the same either way; off is for experiments and for measuring what the rules cost.
  bool rounding_rules = true;
};

struct Stats {
  std::size_t vertices_in = 0;  // distinct input points
  std::size_t crossings = 0;
  std::size_t vertices_out = 0;
};

// The result. Its arrangement keeps the input points, the crossings and the prepared cycles;
// the edges and fragments of steps 2-5 are released before step 6 (a trace hook sees them).
template <Kernel K>
struct BooleanResult {
  Arrangement<K> arrangement;       // owns the vertices the cycles refer to
  std::vector<ResultCycle> cycles;  // irreducible result polygons with their types
  bool unbounded = false;
  Stats stats;

  typename K::Vertex vertex(int id) const { return arrangement.vertex(id); }
};

template <Kernel K>
using TraceHook = std::function<void(Step, const Arrangement<K>&)>;

namespace detail {

// An empty EF table of organisation Table, sized for the fragments of step 4.
template <class Table, Kernel K>
Table make_ef_table(const Arrangement<K>& arr) {
  if constexpr (std::is_same_v<Table, HashEdgeTable>) {
    // Each fragment makes at most one entry in regular output, and rarely two otherwise.
    return HashEdgeTable(arr.polygon[0].fragments.size() + arr.polygon[1].fragments.size(), arr.num_vertices());
  } else {
    return Table();
  }
}

// The procedure polygonoperation [MK89 §3.2] with EF organised as Table: the six steps of
// [MK89 §3.1], one call each.
template <Kernel K, class Table>
BooleanResult<K> run_boolean_op(const BasicPolygon<typename K::Point>& a, const BasicPolygon<typename K::Point>& b,
                                const Options& opt, const TraceHook<K>& trace) {
  const auto hook = [&](Step s, const Arrangement<K>& arr) {
    if (trace) trace(s, arr);
  };
  BooleanResult<K> res;
  Arrangement<K>& arr = res.arrangement;
  const unsigned threads = resolve_threads(opt.threads);
  arr = prepare<K>(a, b, opt.pair_search, threads);  // input: point identities, vertex-complete rings
  hook(Step::prepared, arr);
  normalize_orientations(arr, opt.op, threads);  // step 1
  hook(Step::oriented, arr);
  build_vertex_rings(arr, threads);  // step 2
  hook(Step::vertex_rings, arr);
  insert_intersections(arr, opt.pair_search, threads, opt.rounding_rules);  // step 3
  hook(Step::intersections, arr);
  Incidence inc = classify_fragments(arr, threads);  // step 4
  hook(Step::classified, arr);
  Table ef = make_ef_table<Table>(arr);
  const std::vector<int> isolated_points = select_into_ef(arr, inc, opt.op, opt.regular, ef, threads);  // step 5
  hook(Step::selected, arr);
  // Step 6 needs EF and the vertices only: the per-edge data of steps 2-5 is released
  // first, so that step 6's arrays reuse its memory instead of growing the heap.
  inc = Incidence();
  release_fragments(arr);
  res.cycles = construct_result_polygons(arr, ef, opt.op, isolated_points, threads);  // step 6
  hook(Step::constructed, arr);
  // The unbounded face lies outside both polygons' FAR: in A's region when A is a hole.
  const PolygonType ta = arr.polygon[0].type;
  const PolygonType tb = arr.polygon[1].type;
  res.unbounded = is_face_in_result(opt.op, ta == PolygonType::hole, tb == PolygonType::hole);
  res.stats.vertices_in = arr.points.size();
  res.stats.crossings = static_cast<std::size_t>(arr.num_crossings());
  for (const auto& c : res.cycles) res.stats.vertices_out += c.vertices.size();
  return res;
}

template <Kernel K>
BooleanResult<K> run_boolean_op(const BasicPolygon<typename K::Point>& a, const BasicPolygon<typename K::Point>& b,
                                const Options& opt, const TraceHook<K>& trace) {
  if (opt.ef == EfOrganisation::sorted) return run_boolean_op<K, SortedEdgeTable>(a, b, opt, trace);
  return run_boolean_op<K, HashEdgeTable>(a, b, opt, trace);
}

}  // namespace detail

// Computes `opt.op` on A and B. P is mk::Point (doubles, checked to be finite) or the
// kernel's own point type (for example exact rationals fed back from an earlier result).
template <Kernel K, class P>
BooleanResult<K> boolean_op(const BasicPolygon<P>& a, const BasicPolygon<P>& b, const Options& opt,
                            const TraceHook<K>& trace = {}) {
  if constexpr (std::is_same_v<P, Point>) {
    validate_coordinates(a, "A");
    validate_coordinates(b, "B");
  }
  if constexpr (std::is_same_v<P, typename K::Point>) {
    return detail::run_boolean_op<K>(a, b, opt, trace);
  } else {
    return detail::run_boolean_op<K>(to_kernel_polygon<K>(a), to_kernel_polygon<K>(b), opt, trace);
  }
}

}  // namespace mk
