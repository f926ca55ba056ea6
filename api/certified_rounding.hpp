// Certified rounding of a result: the written coordinates are the nearest doubles when those
// form a valid output, and otherwise (or always, on a grid the user gives) a snap rounding of
// the exact result, rebuilt into polygons by the core itself: the snapped pieces, as the
// rings of one island polygon, are united with the empty polygon, which makes them
// vertex-complete, splits them into irreducible cycles and assembles polygons with holes.
// Their nesting is read by parity, which is the snapped region exactly when every point is
// wound 0 or 1 times: checked (every rebuilt edge must be a snapped piece run in its own
// direction). [Ho99] [HP02] [GM98] [MK89 §2.2] [BRIEF §6a]
// Preconditions: r comes from boolean_op with kernel K. For inexact kernels the result's
// edges may cross: then the output is their nearest doubles as computed, and the report
// says whether it is valid (snap rounding needs a result whose edges do not cross).
#pragma once

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/snap_grid.hpp"
#include "core/boolean_op.hpp"
#include "core/error.hpp"
#include "core/snap_round.hpp"
#include "core/to_output.hpp"

namespace mk {

namespace snapping {

// A result vertex as an exact snap point: input points as they are, crossings by their
// interval box with the rationals made only if a predicate needs them.
inline SnapPoint exact_point(const Point& v, SnapPointStore&) { return SnapPoint::of(v); }
inline SnapPoint exact_point(const RationalPoint& v, SnapPointStore& store) { return store.add(v); }
inline SnapPoint exact_point(const ExactVertex& v, SnapPointStore& store) {
  if (!v.is_crossing) return SnapPoint::of(v.a0);
  if (!std::isfinite(v.lo[0]) || !std::isfinite(v.hi[0]) || !std::isfinite(v.lo[1]) || !std::isfinite(v.hi[1])) {
    return store.add(ExactKernel::exact(v));
  }
  return store.add(v.lo[0], v.hi[0], v.lo[1], v.hi[1], [v] { return ExactKernel::exact(v).x; }, [v] { return ExactKernel::exact(v).y; });
}
// Any other exact vertex type, through its exact coordinates.
inline SnapPoint exact_point(SnapPointStore& store, const std::array<std::string, 2>& text) {
  RationalPoint q{mpq_class(text[0]), mpq_class(text[1])};
  q.x.canonicalize();
  q.y.canonicalize();
  return store.add(q);
}

// The snapped output in grid coordinates and what it took.
struct Snapped {
  Output output;                 // polygons and non-regular parts, coordinates rounded
  std::vector<Pixel> final_pixel;  // per input point: its pixel
  SnapRounded<Pixel> rounding;
  bool valid = false;            // the written doubles are valid
};

// Snap-rounds cycles of exact points onto `grid`, rebuilds polygons through the core, and
// writes the grid points as their nearest doubles.
inline Snapped snap_and_rebuild(const std::vector<SnapPoint>& pts, const std::vector<std::vector<int>>& cycles,
                                const SnapGrid& grid) {
  SnapGeometry geometry(grid);
  Snapped s;
  s.rounding = snap_round(geometry, pts, cycles);
  const auto& hot = s.rounding.hot;
  for (const int h : s.rounding.vertex_pixel) s.final_pixel.push_back(hot[static_cast<std::size_t>(h)]);
  // The rebuild runs on the pixel indices (|index| <= 2^53: exact doubles); scaling by the
  // spacing changes no predicate.
  const auto index_point = [&](int h) {
    return Point{static_cast<double>(hot[static_cast<std::size_t>(h)].x), static_cast<double>(hot[static_cast<std::size_t>(h)].y)};
  };
  Polygon rings;
  std::unordered_map<std::uint64_t, int> piece_direction;  // key -> +1 when run from the smaller id
  for (const auto& ring : s.rounding.rings) {
    rings.rings.emplace_back();
    for (std::size_t k = 0; k < ring.size(); ++k) {
      rings.rings.back().push_back(index_point(ring[k]));
      const int a = ring[k], b = ring[(k + 1) % ring.size()];
      piece_direction[detail::piece_key(a, b)] = a < b ? 1 : -1;
    }
  }
  BooleanResult<ExactKernel> rebuilt;
  try {
    rebuilt = boolean_op<ExactKernel>(rings, Polygon{}, Options{Operation::union_, true, EfOrganisation::hash, PairSearch::sweep});
  } catch (const InvalidInput& e) {
    throw KernelFailure(std::string("snap rounding: the snapped pieces cross (") + e.what() + ")");
  }
  if (rebuilt.arrangement.num_crossings() != 0) throw KernelFailure("snap rounding: the snapped pieces cross");
  // Every rebuilt edge is a snapped piece in its own direction, and every piece is an edge.
  const auto pixel_id = [&](const Point& p) {
    const Pixel px{static_cast<std::int64_t>(p.x), static_cast<std::int64_t>(p.y)};
    return static_cast<int>(std::lower_bound(hot.begin(), hot.end(), px) - hot.begin());
  };
  std::size_t edges = 0;
  for (const auto& c : rebuilt.cycles) {
    if (c.vertices.size() < 3) continue;
    for (std::size_t k = 0; k < c.vertices.size(); ++k) {
      const int a = pixel_id(rebuilt.arrangement.points[static_cast<std::size_t>(c.vertices[k])]);
      const int b = pixel_id(rebuilt.arrangement.points[static_cast<std::size_t>(c.vertices[(k + 1) % c.vertices.size()])]);
      const auto it = piece_direction.find(detail::piece_key(a, b));
      if (it == piece_direction.end() || it->second != (a < b ? 1 : -1)) {
        throw KernelFailure("snap rounding: the rebuilt region differs from the snapped pieces (winding number outside {0, 1})");
      }
      ++edges;
    }
  }
  if (edges != piece_direction.size()) throw KernelFailure("snap rounding: snapped pieces lost in the rebuild");

  // Grid coordinates to doubles.
  const auto coordinate = [&](double index) { return grid.nearest_centre(static_cast<std::int64_t>(index)); };
  const auto to_double = [&](const Point& p) { return Point{coordinate(p.x), coordinate(p.y)}; };
  const Output index_output = to_output<ExactKernel, ExactKernel>(rebuilt, false);
  for (const auto& poly : index_output.polygons) {
    OgcPolygon q;
    for (const Point& p : poly.shell) q.shell.push_back(to_double(p));
    for (const auto& h : poly.holes) {
      q.holes.emplace_back();
      for (const Point& p : h) q.holes.back().push_back(to_double(p));
    }
    s.output.polygons.push_back(std::move(q));
  }
  for (const auto& c : index_output.irreducible) {
    OutputIrreducible o;
    o.type = c.type;
    for (const Point& p : c.vertices) o.vertices.push_back(to_double(p));
    s.output.irreducible.push_back(std::move(o));
  }
  for (const auto& [a, b] : s.rounding.dangling) s.output.dangling_edges.push_back({to_double(index_point(a)), to_double(index_point(b))});
  for (const int p : s.rounding.isolated) s.output.isolated_points.push_back(to_double(index_point(p)));
  // On a grid of doubles the written output is the rebuilt one, scaled exactly; otherwise the
  // rounded grid points are checked again.
  s.valid = grid.is_power_of_two() ? check_ogc_validity<ExactKernel>(index_output.polygons).valid()
                                   : check_ogc_validity<ExactKernel>(s.output.polygons).valid();
  return s;
}

}  // namespace snapping

// Rounds `out` (made by to_output from r) as `mode` and `grid` ask: keeps the nearest doubles
// when allowed and valid, else writes a snap rounding into out.polygons, dangling_edges and
// isolated_points and says so in out.rounding. `grid` empty: the grid of doubles at the scale
// of the largest coordinate, used only when the nearest doubles are not valid.
template <Kernel K>
void certify_rounding(const BooleanResult<K>& r, Output& out, RoundingMode mode, const std::optional<SnapGrid>& grid) {
  RoundingReport& report = out.rounding;
  report = {};
  report.mode = mode;
  report.valid = out.rounded_valid.value_or(false);
  if constexpr (!K::is_exact) {
    // A rounded kernel's polygons were assembled from inexact decisions: what is written is
    // checked as written (one exact sweep).
    if (report.valid && !r.unbounded) report.valid = check_ogc_validity<ExactKernel>(out.polygons).valid();
  }
  if (mode == RoundingMode::nearest || r.unbounded) return;
  if (!grid && report.valid) return;
  if constexpr (!K::is_exact) {
    // Snap rounding needs edges that do not cross; an inexact kernel's may.
    if (!grid) return;
  }
  // The vertices on cycles, as exact points.
  SnapPointStore store;
  std::vector<SnapPoint> pts;
  std::vector<int> local(static_cast<std::size_t>(r.arrangement.num_vertices()), -1);
  std::vector<std::vector<int>> cycles;
  double largest = 0;
  for (const auto& c : r.cycles) {
    cycles.emplace_back();
    for (const int id : c.vertices) {
      if (local[static_cast<std::size_t>(id)] < 0) {
        local[static_cast<std::size_t>(id)] = static_cast<int>(pts.size());
        const auto v = r.vertex(id);
        using Vx = std::remove_cvref_t<decltype(v)>;
        if constexpr (std::is_same_v<Vx, ExactVertex> || std::is_same_v<Vx, RationalPoint> || std::is_same_v<Vx, Point>) {
          pts.push_back(snapping::exact_point(v, store));
        } else {
          pts.push_back(snapping::exact_point(store, K::exact_coordinates(v)));
        }
        const Point a = K::approx(v);
        largest = std::max({largest, std::fabs(a.x), std::fabs(a.y)});
      }
      cycles.back().push_back(local[static_cast<std::size_t>(id)]);
    }
  }
  const SnapGrid doubles_grid = SnapGrid::at_scale_of(largest);
  const SnapGrid& first = grid ? *grid : doubles_grid;
  first.check_range(largest);
  snapping::Snapped s;
  try {
    s = snapping::snap_and_rebuild(pts, cycles, first);
  } catch (const KernelFailure& e) {
    // The snap rounding's exact self-check refused its own rebuild: keep the nearest doubles,
    // say they are not valid and why, rather than write a region that may be wrong.
    report.failure = e.what();
    return;
  } catch (const std::range_error& e) {  // a pixel index beyond 64 bits (SnapGrid::index_of)
    report.failure = e.what();
    return;
  }
  report.snapped = true;
  report.user_grid = grid.has_value();
  report.grid = first.text();
  report.hot_pixels = s.rounding.hot.size();
  report.incidences = s.rounding.incidences;
  report.rounds = s.rounding.rounds;
  // Largest move, in grid units, of a vertex to its pixel's centre (measured in doubles).
  const double g = nearest_double(first.spacing());
  const auto displacement = [&](const std::vector<Pixel>& where) {
    double worst = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Point a = pts[i].approx();
      const double x = static_cast<double>(where[i].x) * g, y = static_cast<double>(where[i].y) * g;  // close enough for a statistic
      worst = std::max(worst, std::hypot(x - a.x, y - a.y) / g);
    }
    return worst;
  };
  if (!s.valid && grid) {
    // The user grid's points are not all doubles, and rounding them broke validity: snap
    // the grid result again onto the grid of doubles.
    SnapPointStore grid_store;
    std::vector<SnapPoint> grid_pts;
    std::vector<std::vector<int>> grid_cycles;
    std::vector<int> at(s.rounding.hot.size(), -1);
    for (const auto& ring : s.rounding.rings) {
      grid_cycles.emplace_back();
      for (const int h : ring) {
        if (at[static_cast<std::size_t>(h)] < 0) {
          at[static_cast<std::size_t>(h)] = static_cast<int>(grid_pts.size());
          const Pixel& p = s.rounding.hot[static_cast<std::size_t>(h)];
          grid_pts.push_back(grid_store.add(RationalPoint{first.centre(p.x), first.centre(p.y)}));
        }
        grid_cycles.back().push_back(at[static_cast<std::size_t>(h)]);
      }
    }
    snapping::Snapped again = snapping::snap_and_rebuild(grid_pts, grid_cycles, doubles_grid);
    report.regridded = true;
    report.grid = doubles_grid.text();
    s.output.polygons = std::move(again.output.polygons);
    s.valid = again.valid;
    report.max_displacement = std::nullopt;
  } else {
    report.max_displacement = displacement(s.final_pixel);
  }
  out.polygons = std::move(s.output.polygons);
  out.dangling_edges = std::move(s.output.dangling_edges);
  out.isolated_points = std::move(s.output.isolated_points);
  report.valid = s.valid;
}

}  // namespace mk
