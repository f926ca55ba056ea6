// The box certificate's tests and its grid: whether vertices' boxes keep clear of the hulls
// of the edges they do not end (rounding_boxes.hpp applies it to a result's rounded cycles;
// rounding_rules.hpp to the input and, through step 3, to the arrangement).
//
// A certificate that rounding a valid exact result to its nearest doubles kept it valid,
// decided in floating point from boxes: each vertex's box holds its exact position and its
// rounded one (so the straight path between them), and each edge, while its ends move,
// stays in the convex hull of their boxes. If no vertex's box meets that hull for an edge
// not ending at the vertex, no vertex ever touches an edge it is not on during the motion;
// the first new contact between two edges would be such a touch (an end of one on the
// other), so none appears, none disappears, and the motion deforms the result without
// changing its topology: the rounded rings are valid with the same holes and touches. This
// is snap rounding's condition with nothing to reroute: every vertex at least a pixel away
// from the edges it is not on [HP02], the pixel being its box, and rounding a continuous
// deformation [GM98]. A pair is cleared when the vertex's box and the hull separate along
// x or y (bounds of each box rounded outward once, the hull's those of its two boxes'
// union), or along the edge's normal, proved with a margin that covers the rounding
// errors of its evaluation (the orientation determinant's error bound [Sh97]). Candidate
// pairs come from a uniform grid of the rounded points.
// [HP02] (vertices half a pixel from edges they are not on) [GM98] [Sh97] [MK89 §3.3]
// Preconditions: the exact result is valid (to_output.hpp); K gives each vertex a box that
// certainly holds it (VertexBoxes). False means "not certified" (the caller checks the
// rounded output in full), never "invalid". The work is bounded: a grid that would visit
// too many cells or pairs gives up.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "core/parallel.hpp"
#include "kernel/point.hpp"

namespace mk {

namespace detail {

// A vertex in the certificate: its rounded point and half-sizes of a box about that point
// holding its exact position too.
struct RoundedVertexBox {
  Point at;
  double rx = 0, ry = 0;
};

// The next double above v (std::nextafter(v, inf) without a library call: the certificate
// asks it several times per edge). Infinity and NaN stay; -0 and +0 go to the smallest
// subnormal.
inline double next_up(double v) {
  if (!(v < HUGE_VAL)) return v;
  if (v == 0) return std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(v);
  return std::bit_cast<double>(v > 0 ? bits + 1 : bits - 1);
}
inline double next_down(double v) { return -next_up(-v); }

// An upper bound on a nonnegative real that one rounding to nearest made v.
inline double rounded_up(double v) { return v > 0 ? next_up(v) : 0.0; }

inline double below(double v) { return next_down(v); }
inline double above(double v) { return next_up(v); }

// Bounds of a box in x and y.
struct BoxBounds {
  double x0, x1, y0, y1;
};

// Bounds holding vertex v's box: its ends computed and rounded outward (the next double
// beyond the nearest holds the exact end; infinity stays).
inline BoxBounds vertex_bounds(const RoundedVertexBox& v) {
  return {below(v.at.x - v.rx), above(v.at.x + v.rx), below(v.at.y - v.ry), above(v.at.y + v.ry)};
}

// Bounds holding the convex hull of two boxes, from bounds holding each: those of their union.
inline BoxBounds hull_bounds(const BoxBounds& a, const BoxBounds& b) {
  return {std::min(a.x0, b.x0), std::max(a.x1, b.x1), std::min(a.y0, b.y0), std::max(a.y1, b.y1)};
}

// Whether two bounds are apart along x or along y (so are the boxes they hold). Without a
// branch per comparison: the grid asks it of every vertex in an edge's cells, and most are
// apart.
inline bool bounds_apart(const BoxBounds& p, const BoxBounds& q) {
  return (p.x1 < q.x0) | (q.x1 < p.x0) | (p.y1 < q.y0) | (q.y1 < p.y0);
}

// The test along the normal of segment uw, made once for the segment and a widening
// (tx, ty): whether a point is farther from the segment's line than the widening reaches.
// |(w - u) x (p - u)| above the reach |dx| ty + |dy| tx: the determinant's error is at
// most (3 + 16 eps) eps (|l| + |r|) [Sh97]; 2^-50 covers it and the rounding of this bound,
// 1 + 2^-48 the rounding of the reach. Products that underflow lose at most 2^-1075 each:
// the last term covers them.
class NormalClearance {
 public:
  NormalClearance(const Point& u, const Point& w, double tx, double ty)
      : u_(u), dx_(w.x - u.x), dy_(w.y - u.y), reach_((std::abs(dx_) * ty + std::abs(dy_) * tx) * (1 + 0x1p-48)) {}
  bool clear(const Point& p) const {
    const double l = dx_ * (p.y - u_.y);
    const double r = dy_ * (p.x - u_.x);
    return std::abs(l - r) > reach_ + (std::abs(l) + std::abs(r)) * 0x1p-50 + 0x1p-1000;
  }

 private:
  Point u_;
  double dx_, dy_, reach_;
};

// The widening for a vertex box of half-sizes (rx, ry) against the hull of boxes of at
// most (hx, hy): the hull lies in the segment widened by the larger box of its ends, and
// the boxes meet when the vertex's point lies in it widened by both.
inline std::array<double, 2> normal_widening(double rx, double ry, double hx, double hy) {
  return {std::max(rounded_up(rx + hx), DBL_MIN), std::max(rounded_up(ry + hy), DBL_MIN)};
}

// Whether vertex box v is clear of the convex hull of the boxes of a and b, along the
// normal of segment ab (clear_of_edge's second test).
inline bool clear_along_normal(const RoundedVertexBox& v, const RoundedVertexBox& a, const RoundedVertexBox& b) {
  const auto [tx, ty] = normal_widening(v.rx, v.ry, std::max(a.rx, b.rx), std::max(a.ry, b.ry));
  return NormalClearance(a.at, b.at, tx, ty).clear(v.at);
}

// Whether vertex box v is clear of the convex hull of the boxes of a and b: apart along x
// or y, else along the segment's normal. With the bounds made already (v's, and the hull's
// from a's and b's), or made here.
inline bool clear_of_edge(const BoxBounds& v_bounds, const BoxBounds& hull, const RoundedVertexBox& v, const RoundedVertexBox& a,
                          const RoundedVertexBox& b) {
  return bounds_apart(v_bounds, hull) || clear_along_normal(v, a, b);
}
inline bool clear_of_edge(const RoundedVertexBox& v, const RoundedVertexBox& a, const RoundedVertexBox& b) {
  return clear_of_edge(vertex_bounds(v), hull_bounds(vertex_bounds(a), vertex_bounds(b)), v, a, b);
}

// Whether the boxes of an edge's two ends are apart (the edge never shrinks to a point).
inline bool ends_apart(const RoundedVertexBox& a, const RoundedVertexBox& b) {
  return bounds_apart(vertex_bounds(a), vertex_bounds(b));
}

// The cell of scaled coordinate f on an axis of n cells: floor(f) clamped to [0, n - 1], NaN
// (infinity times a zero scale) to cell 0. Monotone in f, so closed ranges that meet have
// cell ranges that meet.
inline int clamped_cell(double f, int n) { return !(f >= 1) ? 0 : (f >= n - 1 ? n - 1 : static_cast<int>(f)); }

// A uniform grid over the rounded points. Cell indices are monotone functions of the
// coordinates (a subtraction and a product, each rounding monotonically), so two closed
// ranges that meet have cell ranges that meet.
class BoxGrid {
 public:
  // About `cells` cells (at least one) over the points of v.
  BoxGrid(const std::vector<RoundedVertexBox>& v, std::size_t cells) {
    double x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    for (const auto& b : v) {
      x0_ = std::min(x0_, b.at.x), y0_ = std::min(y0_, b.at.y);
      x1 = std::max(x1, b.at.x), y1 = std::max(y1, b.at.y);
    }
    const double n = static_cast<double>(std::max<std::size_t>(cells, 1));
    const double w = x1 - x0_, h = y1 - y0_;
    constexpr double kMaxSide = 1 << 20;
    if (w > 0 && h > 0 && std::isfinite(w * h)) {
      const double side = std::sqrt(w * h / n);
      nx_ = static_cast<int>(std::clamp(std::ceil(w / side), 1.0, kMaxSide));
      ny_ = static_cast<int>(std::clamp(std::ceil(h / side), 1.0, kMaxSide));
    } else {
      nx_ = w > 0 ? static_cast<int>(std::min(n, kMaxSide)) : 1;
      ny_ = h > 0 ? static_cast<int>(std::min(n, kMaxSide)) : 1;
    }
    while (static_cast<double>(nx_) * ny_ > 4 * n + 16) nx_ = std::max(1, nx_ / 2), ny_ = std::max(1, ny_ / 2);
    // A spread beyond the doubles: one column (or row) holds everything.
    if (!(w > 0 && std::isfinite(w))) nx_ = 1;
    if (!(h > 0 && std::isfinite(h))) ny_ = 1;
    ix_ = nx_ > 1 ? nx_ / w : 0;
    iy_ = ny_ > 1 ? ny_ / h : 0;
    height_ = ny_ > 1 ? 1 / iy_ : 0;
  }
  int col(double x) const { return clamped_cell((x - x0_) * ix_, nx_); }
  int row(double y) const { return clamped_cell((y - y0_) * iy_, ny_); }
  int cells() const { return nx_ * ny_; }
  int rows() const { return ny_; }
  int cell(int c, int r) const { return r * nx_ + c; }
  // A range of y holding every y within `widen` of one that row() puts in row r: the row's
  // exact band widened by a hundredth of a row (which covers the rounding of row()'s
  // subtraction and product: relative 2^-52 each, at most 2^20 rows), by `widen`, and by
  // 2^-47 of the magnitudes (the rounding of this sum, and of row() where the grid's origin
  // is far beyond its extent); the first and last rows (which take everything beyond the
  // grid) and a single row reach to infinity.
  std::array<double, 2> row_band(int r, double widen) const {
    if (ny_ == 1) return {-HUGE_VAL, HUGE_VAL};
    const double lo = (r - 0.01) * height_, hi = (r + 1.01) * height_;
    const double reach = widen * (1 + 0x1p-50) + 0x1p-47 * (std::abs(y0_) + std::abs(hi) + widen);
    return {r == 0 ? -HUGE_VAL : y0_ + lo - reach, r == ny_ - 1 ? HUGE_VAL : y0_ + hi + reach};
  }
  // The height of a row (at least): 0 for a single row.
  double row_height() const { return height_; }

 private:
  double x0_ = HUGE_VAL, y0_ = HUGE_VAL;
  double ix_ = 0, iy_ = 0;
  double height_ = 0;  // 1 / iy_, rounded: a row's height within a relative 2^-52
  int nx_ = 1, ny_ = 1;
};

// The certificate over vertex boxes and edges between them (indices into `v`), with the
// candidate pairs from the grid, or from all pairs (`all_pairs`, for tests). A vertex whose
// box is its point has not moved; a vertex and an edge of which none moved are never
// tested (the exact result has them apart). The moved vertices are listed in the grid's
// cells and every edge visits the cells its hull may meet; the other vertices against the
// edges with a moved end: when those edges are few (a smooth curve of many input points
// with a few crossings), they are listed in the cells and each vertex looks in its own;
// otherwise the vertices are listed too. Edges are searched in parts on up to `threads`
// threads.
inline bool boxes_keep_topology(const std::vector<RoundedVertexBox>& v, const std::vector<std::array<int, 2>>& edges,
                                bool all_pairs = false, unsigned threads = 1) {
  const auto moved = [&](int k) {
    const auto& b = v[static_cast<std::size_t>(k)];
    return b.rx != 0 || b.ry != 0;
  };
  // Over [0, n) in parts on the threads: how many i step(i, ok) counts, or none when some
  // step cleared ok.
  const auto tally = [&](std::size_t n, auto&& step) -> std::optional<std::size_t> {
    const std::size_t parts = threads > 1 && n >= kParallelWork ? 8 * static_cast<std::size_t>(threads) : 1;
    std::vector<std::size_t> counts(parts, 0);
    std::atomic<bool> all_ok{true};
    run_tasks(threads, parts, [&](std::size_t part) {
      std::size_t count = 0;
      bool ok = true;
      for (std::size_t i = n * part / parts, last = n * (part + 1) / parts; i < last; ++i) count += step(i, ok);
      counts[part] = count;
      if (!ok) all_ok = false;
    });
    if (!all_ok) return std::nullopt;
    std::size_t total = 0;
    for (const std::size_t c : counts) total += c;
    return total;
  };
  // Every vertex's bounds, and how many moved.
  const auto bounds = std::make_unique_for_overwrite<BoxBounds[]>(v.size());
  const std::optional<std::size_t> moved_count = tally(v.size(), [&](std::size_t k, bool& ok) {
    ok = ok && std::isfinite(v[k].rx) && std::isfinite(v[k].ry);
    bounds[k] = vertex_bounds(v[k]);
    return moved(static_cast<int>(k));
  });
  if (!moved_count) return false;
  const std::size_t num_moved = *moved_count;
  const auto edge_hull = [&](const std::array<int, 2>& e) {
    return hull_bounds(bounds[static_cast<std::size_t>(e[0])], bounds[static_cast<std::size_t>(e[1])]);
  };
  // Every edge keeps two ends apart, and how many edges have a moved end.
  const std::optional<std::size_t> moved_edge_count = tally(edges.size(), [&](std::size_t i, bool& ok) {
    const auto& [a, b] = edges[i];
    ok = ok && bounds_apart(bounds[static_cast<std::size_t>(a)], bounds[static_cast<std::size_t>(b)]);
    return moved(a) || moved(b);
  });
  if (!moved_edge_count) return false;
  const std::size_t moved_edges = *moved_edge_count;
  const auto clear = [&](int k, const std::array<int, 2>& e) {
    if (k == e[0] || k == e[1]) return true;
    const auto at = [&](int j) -> const RoundedVertexBox& { return v[static_cast<std::size_t>(j)]; };
    return clear_of_edge(bounds[static_cast<std::size_t>(k)], edge_hull(e), at(k), at(e[0]), at(e[1]));
  };
  if (all_pairs) {
    for (const auto& e : edges) {
      const bool edge_moved = moved(e[0]) || moved(e[1]);
      for (std::size_t k = 0; k < v.size(); ++k) {
        if ((edge_moved || moved(static_cast<int>(k))) && !clear(static_cast<int>(k), e)) return false;
      }
    }
    return true;
  }
  if (num_moved == 0) return true;  // nothing moved: no pair to test
  const std::size_t still = v.size() - num_moved;
  const bool list_edges = 8 * moved_edges <= still;  // the vertices that did not move look up the edges
  const BoxGrid grid(v, list_edges ? num_moved + moved_edges : v.size());
  const std::size_t cells = static_cast<std::size_t>(grid.cells());
  std::size_t budget = 64 * (v.size() + edges.size()) + (1u << 20);
  // The cells an edge's hull may meet, each once, as runs of consecutive cells in a row: the
  // edge cut into pieces about one cell long, each piece's box widened by the hull's
  // half-sizes and by the error of computing the piece's ends (u + t (w - u): at most
  // 16 eps (|u| + |w|) per coordinate). f(row, c0, c1) returns false to stop; so does this,
  // when `steps` (every cell looked at, the ones already visited included: a shallow
  // crossing's wide box can make each piece span the grid) passes `limit`.
  const auto for_each_run = [&](const std::array<int, 2>& e, auto&& f, std::size_t& steps, std::size_t limit) {
    const auto& a = v[static_cast<std::size_t>(e[0])];
    const auto& b = v[static_cast<std::size_t>(e[1])];
    const Point u = a.at, w = b.at;
    const auto run = [&](int r, int c0, int c1) {
      steps += static_cast<std::size_t>(c1 - c0 + 1);
      return steps <= limit && f(r, c0, c1);
    };
    // An edge whose hull's bounds meet at most four cells visits them all; a longer one goes
    // piece by piece.
    {
      const BoxBounds hull = edge_hull(e);
      const int c0 = grid.col(hull.x0), c1 = grid.col(hull.x1), r0 = grid.row(hull.y0), r1 = grid.row(hull.y1);
      if ((c1 - c0 + 1) * (r1 - r0 + 1) <= 4) {
        for (int r = r0; r <= r1; ++r) {
          if (!run(r, c0, c1)) return false;
        }
        return true;
      }
    }
    // As many pieces as the edge crosses cells along its shorter axis: a piece's box then
    // spans about two cells across, so it visits about twice the cells the edge passes,
    // while each piece's box costs more than visiting a cell (a long edge along a row is
    // one or two pieces, not one per column). Per row, the cells outside the previous
    // piece's box: none, one run or two.
    const double mx = rounded_up(rounded_up(std::max(a.rx, b.rx) + rounded_up(0x1p-49 * (std::abs(u.x) + std::abs(w.x)))) + DBL_MIN);
    const double my = rounded_up(rounded_up(std::max(a.ry, b.ry) + rounded_up(0x1p-49 * (std::abs(u.y) + std::abs(w.y)))) + DBL_MIN);
    const int pieces = std::min(std::abs(grid.col(u.x) - grid.col(w.x)), std::abs(grid.row(u.y) - grid.row(w.y))) + 1;
    const double dx = w.x - u.x, dy = w.y - u.y;
    Point p = u;
    int pc0 = 1, pc1 = 0, pr0 = 1, pr1 = 0;  // the previous piece's cells
    for (int j = 1; j <= pieces; ++j) {
      const double t = static_cast<double>(j) / pieces;
      const Point q = j == pieces ? w : Point{u.x + t * dx, u.y + t * dy};
      const int c0 = grid.col(below(std::min(p.x, q.x) - mx)), c1 = grid.col(above(std::max(p.x, q.x) + mx));
      const int r0 = grid.row(below(std::min(p.y, q.y) - my)), r1 = grid.row(above(std::max(p.y, q.y) + my));
      for (int r = r0; r <= r1; ++r) {
        if (r < pr0 || r > pr1 || pc1 < c0 || c1 < pc0) {
          if (!run(r, c0, c1)) return false;
          continue;
        }
        steps += static_cast<std::size_t>(std::min(c1, pc1) - std::max(c0, pc0) + 1);  // looked at, visited before
        if (c0 < pc0 && !run(r, c0, pc0 - 1)) return false;
        if (pc1 < c1 && !run(r, pc1 + 1, c1)) return false;
        if (steps > limit) return false;
      }
      pc0 = c0, pc1 = c1, pr0 = r0, pr1 = r1;
      p = q;
    }
    return true;
  };
  // The same cells one by one.
  const auto for_each_cell = [&](const std::array<int, 2>& e, auto&& f, std::size_t& steps, std::size_t limit) {
    return for_each_run(e, [&](int r, int c0, int c1) {
      for (int c = c0; c <= c1; ++c) {
        if (!f(static_cast<std::size_t>(grid.cell(c, r)))) return false;
      }
      return true;
    }, steps, limit);
  };
  // The vertices listed, by their boxes' bounds and index (complemented for a vertex that
  // did not move), in each cell their box meets, the cells' lists one after another (so
  // the cells of a run in a row are one range). Each listed vertex's cells are found on the
  // threads; the lists are then counted and filled in bands of rows (consecutive cells),
  // each band by one task going through the vertices in order: the same lists in the same
  // order on any number of threads.
  std::vector<int> start(cells + 1, 0);
  std::vector<int> moved_in_cell(cells, 0);
  const auto listed = [&](std::size_t k) { return moved(static_cast<int>(k)) || !list_edges; };
  const unsigned list_threads = threads_for(v.size(), threads);
  // None (c1 < c0) for a vertex not listed; each written below (no zeroing pass first).
  const auto spans = std::make_unique_for_overwrite<std::array<int, 4>[]>(v.size());
  std::size_t entries = 0;
  {
    const std::size_t parts = list_threads > 1 ? 8 * static_cast<std::size_t>(list_threads) : 1;
    std::vector<std::size_t> part_entries(parts, 0);
    run_tasks(list_threads, parts, [&](std::size_t part) {
      std::size_t count = 0;
      for (std::size_t k = v.size() * part / parts, last = v.size() * (part + 1) / parts; k < last; ++k) {
        if (!listed(k)) {
          spans[k] = {0, -1, 0, -1};
          continue;
        }
        const BoxBounds& bk = bounds[k];
        const auto& sp = spans[k] = {grid.col(bk.x0), grid.col(bk.x1), grid.row(bk.y0), grid.row(bk.y1)};
        count += static_cast<std::size_t>(sp[1] - sp[0] + 1) * static_cast<std::size_t>(sp[3] - sp[2] + 1);
      }
      part_entries[part] = count;
    });
    for (const std::size_t e : part_entries) entries += e;
    if (entries > budget) return false;
  }
  const int bands = list_threads > 1 ? 2 * static_cast<int>(list_threads) : 1;
  const auto band_rows = [&](int band) {  // the rows [first, last) of band `band`
    return std::array<int, 2>{grid.rows() * band / bands, grid.rows() * (band + 1) / bands};
  };
  // Calls f(k, c, r) for every cell (c, r) of band `band` that listed vertex k's box meets,
  // k in order.
  const auto for_each_in_band = [&](int band, auto&& f) {
    const auto [r_lo, r_hi] = band_rows(band);
    for (std::size_t k = 0; k < v.size(); ++k) {
      const auto& sp = spans[k];
      const int r0 = std::max(sp[2], r_lo), r1 = std::min(sp[3], r_hi - 1);
      for (int r = r0; r <= r1; ++r) {
        for (int c = sp[0]; c <= sp[1]; ++c) f(k, c, r);
      }
    }
  };
  run_tasks(list_threads, static_cast<std::size_t>(bands), [&](std::size_t band) {
    for_each_in_band(static_cast<int>(band), [&](std::size_t k, int c, int r) {
      const auto cell = static_cast<std::size_t>(grid.cell(c, r));
      ++start[cell + 1];
      moved_in_cell[cell] += moved(static_cast<int>(k));
    });
  });
  // The work the edges will do, estimated before doing it: each vertex brings about two edges
  // to its cell, and each edge there tests the cell's moved vertices (and the others when an
  // end moved). Points crowding cells with moved ones are left to the full check.
  {
    std::size_t estimate = 0;
    for (std::size_t c = 0; c < cells; ++c) {
      const std::size_t m = static_cast<std::size_t>(moved_in_cell[c]), o = static_cast<std::size_t>(start[c + 1]) - m;
      estimate += 2 * m * (m + o) + (m > 0 ? 2 * m * o : 0);
    }
    if (estimate > budget) return false;
  }
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  // Each listed vertex's bounds and index, copied in (the cells are read in the edges'
  // order, the boxes are stored in the cycles'). Both arrays are written first by the
  // bands' tasks, not zeroed before (fresh pages cost more than the writes: star 1e4's
  // 10 MB took 5 ms to zero); start[c] is cell c's cursor while filling, and ends at the
  // start of cell c + 1, so it moves back by one after.
  const auto in_cell = std::make_unique_for_overwrite<BoxBounds[]>(entries);
  const auto in_cell_k = std::make_unique_for_overwrite<int[]>(entries);
  run_tasks(list_threads, static_cast<std::size_t>(bands), [&](std::size_t band) {
    for_each_in_band(static_cast<int>(band), [&](std::size_t k, int c, int r) {
      const auto at = static_cast<std::size_t>(start[static_cast<std::size_t>(grid.cell(c, r))]++);
      in_cell[at] = bounds[k];
      in_cell_k[at] = moved(static_cast<int>(k)) ? static_cast<int>(k) : ~static_cast<int>(k);
    });
  });
  std::copy_backward(start.begin(), start.end() - 1, start.end());
  start[0] = 0;
  // Every edge against the vertices listed in its runs of cells (the moved ones, and the
  // others when an end moved and they are listed): the boxes apart from the edge's hull's
  // are passed over by four comparisons (as clear_of_edge would pass them), the rest tested.
  const std::size_t parts = threads > 1 && edges.size() >= kParallelWork ? 8 * static_cast<std::size_t>(threads) : 1;
  const std::size_t part_budget = budget / parts;
  std::atomic<bool> refused{false};
  run_tasks(threads, parts, [&](std::size_t part) {
    std::size_t work = 0, steps = 0;
    const std::size_t first = edges.size() * part / parts, last = edges.size() * (part + 1) / parts;
    for (std::size_t i = first; i < last && !refused.load(std::memory_order_relaxed); ++i) {
      const auto& e = edges[i];
      const bool edge_moved = moved(e[0]) || moved(e[1]);  // then all listed vertices, else the moved ones
      const RoundedVertexBox& a = v[static_cast<std::size_t>(e[0])];
      const RoundedVertexBox& b = v[static_cast<std::size_t>(e[1])];
      const BoxBounds hull = edge_hull(e);
      // The entries whose bounds meet the hull's, gathered without a branch per entry (most
      // are apart, which a branch would mispredict often), then tested.
      const auto scan = [&](int from, int to) {
        work += static_cast<std::size_t>(to - from);
        constexpr int kChunk = 64;
        int near[kChunk];
        for (int chunk = from; chunk < to; chunk += kChunk) {
          const int last = std::min(to, chunk + kChunk);
          int found = 0;
          for (int k = chunk; k < last; ++k) {
            near[found] = k;
            found += !bounds_apart(in_cell[static_cast<std::size_t>(k)], hull);
          }
          for (int j = 0; j < found; ++j) {
            int id = in_cell_k[static_cast<std::size_t>(near[j])];
            if (id < 0) {
              if (!edge_moved) continue;
              id = ~id;
            }
            if (id == e[0] || id == e[1]) continue;
            if (!clear_along_normal(v[static_cast<std::size_t>(id)], a, b)) return false;
          }
        }
        return true;
      };
      const bool ok = for_each_run(e, [&](int r, int c0, int c1) {
        const std::size_t from = static_cast<std::size_t>(grid.cell(c0, r)), to = static_cast<std::size_t>(grid.cell(c1, r)) + 1;
        ++work;
        if (!scan(start[from], start[to])) return false;
        return work <= part_budget;
      }, steps, part_budget);
      if (!ok) refused = true;
    }
  });
  if (refused || !list_edges || moved_edges == 0) return !refused;
  // The vertices that did not move against the edges with a moved end, listed in the cells
  // they visit; a vertex's box is its point, in one cell.
  std::vector<int> edge_start(cells + 1, 0);
  std::size_t edge_entries = 0, edge_steps = 0;
  for (const auto& e : edges) {
    if (!moved(e[0]) && !moved(e[1])) continue;
    const bool ok = for_each_cell(e, [&](std::size_t cell) {
      ++edge_start[cell + 1];
      return ++edge_entries <= budget;
    }, edge_steps, budget);
    if (!ok) return false;
  }
  for (std::size_t i = 1; i < edge_start.size(); ++i) edge_start[i] += edge_start[i - 1];
  std::vector<int> edge_in_cell(edge_entries);
  {
    std::vector<int> fill(edge_start.begin(), edge_start.end() - 1);
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const auto& e = edges[i];
      if (!moved(e[0]) && !moved(e[1])) continue;
      std::size_t steps = 0;  // the same cells as the count above, which stayed within the budget
      for_each_cell(e, [&](std::size_t cell) {
        edge_in_cell[static_cast<std::size_t>(fill[cell]++)] = static_cast<int>(i);
        return true;
      }, steps, std::numeric_limits<std::size_t>::max());
    }
  }
  const std::size_t vertex_parts = threads > 1 && v.size() >= kParallelWork ? 8 * static_cast<std::size_t>(threads) : 1;
  const std::size_t vertex_budget = budget / vertex_parts;
  run_tasks(threads, vertex_parts, [&](std::size_t part) {
    std::size_t work = 0;
    const std::size_t first = v.size() * part / vertex_parts, last = v.size() * (part + 1) / vertex_parts;
    for (std::size_t k = first; k < last && !refused.load(std::memory_order_relaxed); ++k) {
      if (moved(static_cast<int>(k))) continue;
      const std::size_t cell = static_cast<std::size_t>(grid.cell(grid.col(v[k].at.x), grid.row(v[k].at.y)));
      work += static_cast<std::size_t>(edge_start[cell + 1] - edge_start[cell]);
      for (int i = edge_start[cell]; i < edge_start[cell + 1]; ++i) {
        if (!clear(static_cast<int>(k), edges[static_cast<std::size_t>(edge_in_cell[static_cast<std::size_t>(i)])])) work = vertex_budget + 1;
      }
      if (work > vertex_budget) {
        refused = true;
        return;
      }
    }
  });
  return !refused;
}

// boxes_keep_topology for points that did not move, each with a box of half-size `half`
// about it, against edges between them (rule I of separation_rules.hpp): true when no
// point's box meets the hull of an edge it does not end. The points are listed in the grid's
// cells their boxes meet; each edge visits, row by row, the cells its hull may meet in that
// row (the segment's x over the row's band, widened by the half-size and by its rounding):
// about as many cells as the segment crosses, where the pieces of boxes_keep_topology,
// made for boxes of every size, visit about twice as many and cost more each. False also
// when the work passes a budget linear in the input (points crowding cells that many edges
// cross), which leaves the decision to the general certificate.
inline bool points_clear_of_edges(const std::vector<Point>& points, double half, const std::vector<std::array<int, 2>>& edges,
                                  unsigned threads = 1) {
  if (!(half >= 0 && half < HUGE_VAL)) return false;
  std::vector<RoundedVertexBox> v(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) v[k] = {points[k], half, half};
  // Half as many cells as points: an edge's rows cost more than its cells' points (star 1e4's
  // input: 3.65 ms on two threads, against 4.2 with as many cells as points, 4.6 with twice).
  const BoxGrid grid(v, v.size() / 2 + 1);
  const std::size_t cells = static_cast<std::size_t>(grid.cells());
  const std::size_t budget = 64 * (v.size() + edges.size()) + (1u << 20);
  // The points listed by cell (counted, then placed), each with its index.
  std::vector<int> start(cells + 1, 0);
  std::vector<std::array<int, 4>> spans(v.size());
  std::size_t entries = 0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const BoxBounds b = vertex_bounds(v[k]);
    const auto& sp = spans[k] = {grid.col(b.x0), grid.col(b.x1), grid.row(b.y0), grid.row(b.y1)};
    entries += static_cast<std::size_t>(sp[1] - sp[0] + 1) * static_cast<std::size_t>(sp[3] - sp[2] + 1);
    if (entries > budget) return false;
    for (int r = sp[2]; r <= sp[3]; ++r) {
      for (int c = sp[0]; c <= sp[1]; ++c) ++start[static_cast<std::size_t>(grid.cell(c, r)) + 1];
    }
  }
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  // Each entry's point beside its index: an edge reads its cells' points in a run.
  std::vector<int> in_cell(entries);
  std::vector<Point> in_cell_at(entries);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < v.size(); ++k) {
      const auto& sp = spans[k];
      for (int r = sp[2]; r <= sp[3]; ++r) {
        for (int c = sp[0]; c <= sp[1]; ++c) {
          const auto at = static_cast<std::size_t>(fill[static_cast<std::size_t>(grid.cell(c, r))]++);
          in_cell[at] = static_cast<int>(k);
          in_cell_at[at] = points[k];
        }
      }
    }
  }
  // (Named, not bound: clang 14, the fuzzers' compiler, cannot capture structured bindings.)
  const std::array<double, 2> widening = normal_widening(half, half, half, half);
  const double tx = widening[0], ty = widening[1];
  const unsigned t = threads_for(edges.size(), threads);
  const std::size_t parts = t > 1 ? 8 * static_cast<std::size_t>(t) : 1;
  const std::size_t part_budget = budget / parts;
  std::atomic<bool> refused{false};
  run_tasks(t, parts, [&](std::size_t part) {
    std::size_t work = 0;
    for (std::size_t i = edges.size() * part / parts, last = edges.size() * (part + 1) / parts;
         i < last && !refused.load(std::memory_order_relaxed); ++i) {
      const auto [ia, ib] = edges[i];
      const RoundedVertexBox& a = v[static_cast<std::size_t>(ia)];
      const RoundedVertexBox& b = v[static_cast<std::size_t>(ib)];
      const BoxBounds hull = hull_bounds(vertex_bounds(a), vertex_bounds(b));
      const Point u = a.at, w = b.at;
      const NormalClearance normal(u, w, tx, ty);
      const double dx = w.x - u.x, dy = w.y - u.y;
      // Row by row: a point q of the hull in row r has q.y in the row's band, so lies within
      // the half-size of a point s of the segment with s.y in the band widened by it; s.x is
      // x(s.y) on the segment's line, computed with an error under 2^-48 (|u.x| + 2 |dx|)
      // when the segment spans a row or more (|y - u.y| at most |dy| and a row then), else
      // the hull's x range is taken whole.
      // (The widening also covers the rounding of the sums that apply it: at most 2^-53
      // (|u.x| + 2 |dx| + widen).)
      const bool steep = std::abs(dy) >= grid.row_height() && dy != 0;
      const double slope = steep ? dx / dy : 0;
      const double widen =
          rounded_up(rounded_up(half * (1 + 0x1p-50)) + rounded_up(0x1p-47 * (std::abs(u.x) + 2 * std::abs(dx))) + DBL_MIN);
      const double y_lo = std::min(u.y, w.y), y_hi = std::max(u.y, w.y);
      bool ok = true;
      for (int r = grid.row(hull.y0), r1 = grid.row(hull.y1); r <= r1 && ok; ++r) {
        double x0 = hull.x0, x1 = hull.x1;
        if (steep) {
          // The band widened by the half-size and cut to the segment's y: empty, no point
          // of the hull in this row.
          const auto band = grid.row_band(r, half);
          const double s0 = std::max(band[0], y_lo), s1 = std::min(band[1], y_hi);
          if (s0 > s1) continue;
          const double xa = u.x + (s0 - u.y) * slope, xb = u.x + (s1 - u.y) * slope;
          x0 = std::max(x0, std::min(xa, xb) - widen);
          x1 = std::min(x1, std::max(xa, xb) + widen);
          if (x0 > x1) continue;
        }
        const int from = start[static_cast<std::size_t>(grid.cell(grid.col(x0), r))];
        const int to = start[static_cast<std::size_t>(grid.cell(grid.col(x1), r)) + 1];
        work += static_cast<std::size_t>(to - from) + 1;
        // Almost every point is clear along the normal; the rest by their bounds, or the
        // edge's own ends.
        for (int j = from; j < to; ++j) {
          if (normal.clear(in_cell_at[static_cast<std::size_t>(j)])) continue;
          const int k = in_cell[static_cast<std::size_t>(j)];
          if (k != ia && k != ib && !bounds_apart(vertex_bounds(v[static_cast<std::size_t>(k)]), hull)) ok = false;
        }
      }
      if (!ok || work > part_budget) refused = true;
    }
  });
  return !refused;
}

}  // namespace detail

}  // namespace mk
