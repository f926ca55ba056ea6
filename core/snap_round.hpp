// Iterated snap rounding of a result's cycles onto a grid: the hot pixels are those holding a
// vertex; every edge becomes the path through the centres of the hot pixels it meets, in
// order along it; then, until none does, every piece of a path that meets a hot pixel other
// than its ends is routed through that pixel's centre too, which keeps every vertex at
// least half a pixel from the pieces it is not on. Pieces that coincide with opposite
// directions cancel; what remains (each piece once, with its direction) is decomposed into
// closed rings.
// [Ho99] (snap rounding) [GM98] (a continuous deformation: faces may collapse, never invert)
// [HP02] (iterated snap rounding) [BHO07] (hot pixels from the vertices only, since the
// edges do not cross)
// Preconditions: the cycles' edges do not cross each other (they may share vertices); G is
// a snap geometry (see core/hot_pixels.hpp). Throws KernelFailure when the pieces would
// cover an edge twice in one direction (the winding number would leave {0, 1}), which the
// deformation argument excludes: it is checked, not assumed.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/hot_pixels.hpp"

namespace mk {

template <class Px>
struct SnapRounded {
  std::vector<Px> hot;                        // the hot pixels, sorted
  std::vector<int> vertex_pixel;              // per input point: its hot pixel
  std::vector<std::vector<int>> rings;        // closed rings of hot pixel ids (the regular part)
  std::vector<std::pair<int, int>> dangling;  // snapped two-sided parts not on the rings
  std::vector<int> isolated;                  // snapped one-sided parts not on anything else
  int rounds = 0;                             // routing rounds until no piece met another hot pixel
  std::size_t incidences = 0;                 // edge-pixel incidences besides the edges' own ends
};

namespace detail {

inline std::uint64_t piece_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(a, b))) << 32) |
         static_cast<std::uint32_t>(std::max(a, b));
}

// Orders the pixels `met` by segment u -> w runs through them (the order of their centres'
// projections on it: for equal axis-parallel squares that is the order of traversal).
template <class G, class Px>
void order_along(const typename G::Point& u, const typename G::Point& w, const std::vector<Px>& hot, std::vector<int>& met) {
  std::sort(met.begin(), met.end(), [&](int a, int b) {
    const Sign s = G::compare_along(u, w, hot[static_cast<std::size_t>(a)], hot[static_cast<std::size_t>(b)]);
    return s == Sign::negative || (s == Sign::zero && hot[static_cast<std::size_t>(a)] < hot[static_cast<std::size_t>(b)]);
  });
}

}  // namespace detail

// Snap-rounds cycles of point indices (3+ vertices: region boundaries; 2: two-sided parts;
// 1: one-sided parts) given with exact points `pts`.
template <class G>
auto snap_round(G& g, const std::vector<typename G::Point>& pts, const std::vector<std::vector<int>>& cycles,
                int max_rounds = 64) {
  using Point = typename G::Point;
  using Px = decltype(g.pixel_of(pts.front()));
  SnapRounded<Px> out;
  if (pts.empty()) return out;
  // Hot pixels.
  std::vector<Px> pixel_of_point(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) pixel_of_point[i] = g.pixel_of(pts[i]);
  out.hot = pixel_of_point;
  std::sort(out.hot.begin(), out.hot.end());
  out.hot.erase(std::unique(out.hot.begin(), out.hot.end()), out.hot.end());
  const auto hot_id = [&](const Px& p) {
    return static_cast<int>(std::lower_bound(out.hot.begin(), out.hot.end(), p) - out.hot.begin());
  };
  out.vertex_pixel.resize(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) out.vertex_pixel[i] = hot_id(pixel_of_point[i]);

  // Round 0: the edges themselves, each once (as segments from the smaller point index).
  std::vector<std::pair<int, int>> segments;
  std::unordered_map<std::uint64_t, int> segment_of;
  for (const auto& c : cycles) {
    if (c.size() < 2) continue;
    for (std::size_t k = 0; k < (c.size() == 2 ? 1 : c.size()); ++k) {
      const int u = c[k], w = c[(k + 1) % c.size()];
      if (segment_of.emplace(detail::piece_key(u, w), static_cast<int>(segments.size())).second) {
        segments.push_back({std::min(u, w), std::max(u, w)});
      }
    }
  }
  std::vector<std::vector<int>> met = hot_pixels_met(g, pts, pixel_of_point, segments, out.hot);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    out.incidences += met[s].size();
    detail::order_along<G>(pts[static_cast<std::size_t>(segments[s].first)], pts[static_cast<std::size_t>(segments[s].second)],
                           out.hot, met[s]);
  }
  // Each directed edge's path of hot pixels.
  const auto path_of = [&](int u, int w) {
    const int s = segment_of.at(detail::piece_key(u, w));
    std::vector<int> path{out.vertex_pixel[static_cast<std::size_t>(u)]};
    if (u < w) {
      path.insert(path.end(), met[static_cast<std::size_t>(s)].begin(), met[static_cast<std::size_t>(s)].end());
    } else {
      path.insert(path.end(), met[static_cast<std::size_t>(s)].rbegin(), met[static_cast<std::size_t>(s)].rend());
    }
    if (path.back() != out.vertex_pixel[static_cast<std::size_t>(w)]) path.push_back(out.vertex_pixel[static_cast<std::size_t>(w)]);
    return path;
  };
  std::vector<std::vector<int>> boundary_paths, dangling_paths;
  for (const auto& c : cycles) {
    if (c.size() == 1) {
      out.isolated.push_back(out.vertex_pixel[static_cast<std::size_t>(c[0])]);
    } else if (c.size() == 2) {
      dangling_paths.push_back(path_of(c[0], c[1]));
    } else {
      for (std::size_t k = 0; k < c.size(); ++k) boundary_paths.push_back(path_of(c[k], c[(k + 1) % c.size()]));
    }
  }

  // Iterated rounds: pieces between consecutive centres, routed through the hot pixels they
  // meet besides their ends.
  std::vector<Point> centre(out.hot.size());
  for (std::size_t h = 0; h < out.hot.size(); ++h) centre[h] = g.centre(out.hot[h]);
  std::vector<Px> centre_pixel = out.hot;
  for (;;) {
    std::vector<std::pair<int, int>> pieces;
    std::unordered_map<std::uint64_t, int> piece_of;
    for (const auto* paths : {&boundary_paths, &dangling_paths}) {
      for (const auto& path : *paths) {
        for (std::size_t k = 0; k + 1 < path.size(); ++k) {
          const int a = path[k], b = path[k + 1];
          if (piece_of.emplace(detail::piece_key(a, b), static_cast<int>(pieces.size())).second) {
            pieces.push_back({std::min(a, b), std::max(a, b)});
          }
        }
      }
    }
    std::vector<std::vector<int>> through = hot_pixels_met(g, centre, centre_pixel, pieces, out.hot);
    bool rerouted = false;
    for (std::size_t s = 0; s < pieces.size(); ++s) {
      if (through[s].empty()) continue;
      rerouted = true;
      detail::order_along<G>(centre[static_cast<std::size_t>(pieces[s].first)],
                             centre[static_cast<std::size_t>(pieces[s].second)], out.hot, through[s]);
    }
    if (!rerouted) break;
    if (++out.rounds > max_rounds) throw KernelFailure("snap rounding: pieces still meet hot pixels after " + std::to_string(max_rounds) + " rounds");
    for (auto* paths : {&boundary_paths, &dangling_paths}) {
      for (auto& path : *paths) {
        std::vector<int> routed{path.front()};
        for (std::size_t k = 0; k + 1 < path.size(); ++k) {
          const int a = path[k], b = path[k + 1];
          const auto& via = through[static_cast<std::size_t>(piece_of.at(detail::piece_key(a, b)))];
          if (a < b) {
            routed.insert(routed.end(), via.begin(), via.end());
          } else {
            routed.insert(routed.end(), via.rbegin(), via.rend());
          }
          routed.push_back(b);
        }
        path = std::move(routed);
      }
    }
  }

  // Net multiplicities: pieces of opposite directions cancel.
  std::unordered_map<std::uint64_t, int> net;
  for (const auto& path : boundary_paths) {
    for (std::size_t k = 0; k + 1 < path.size(); ++k) net[detail::piece_key(path[k], path[k + 1])] += path[k] < path[k + 1] ? 1 : -1;
  }
  std::vector<std::vector<int>> leaving(out.hot.size());  // directed pieces by start pixel
  for (const auto& [key, m] : net) {
    if (m == 0) continue;
    if (m != 1 && m != -1) {
      throw KernelFailure("snap rounding: a piece is covered " + std::to_string(m > 0 ? m : -m) +
                          " times in one direction (winding number outside {0, 1})");
    }
    const int lo = static_cast<int>(key >> 32), hi = static_cast<int>(key & 0xffffffffu);
    if (m > 0) {
      leaving[static_cast<std::size_t>(lo)].push_back(hi);
    } else {
      leaving[static_cast<std::size_t>(hi)].push_back(lo);
    }
  }
  // Closed rings: walk unused pieces until back at the start (in-degree equals out-degree at
  // every pixel, the pieces being a sum of closed paths).
  for (std::size_t start = 0; start < leaving.size(); ++start) {
    while (!leaving[start].empty()) {
      std::vector<int> ring{static_cast<int>(start)};
      int at = static_cast<int>(start);
      for (;;) {
        auto& out_of = leaving[static_cast<std::size_t>(at)];
        if (out_of.empty()) throw KernelFailure("snap rounding: the pieces do not close into rings");
        const int next = out_of.back();
        out_of.pop_back();
        if (next == static_cast<int>(start)) break;
        ring.push_back(next);
        at = next;
      }
      out.rings.push_back(std::move(ring));
    }
  }

  // Non-regular parts: two-sided pieces off the rings, points off everything.
  std::unordered_map<std::uint64_t, bool> taken;
  std::vector<char> used(out.hot.size(), 0);
  for (const auto& [key, m] : net) {
    if (m == 0) continue;
    taken[key] = true;
    used[key >> 32] = used[key & 0xffffffffu] = 1;
  }
  for (const auto& path : dangling_paths) {
    if (path.size() == 1) {
      out.isolated.push_back(path[0]);
      continue;
    }
    for (std::size_t k = 0; k + 1 < path.size(); ++k) {
      if (!taken.emplace(detail::piece_key(path[k], path[k + 1]), true).second) continue;
      out.dangling.push_back({path[k], path[k + 1]});
      used[static_cast<std::size_t>(path[k])] = used[static_cast<std::size_t>(path[k + 1])] = 1;
    }
  }
  std::vector<int> points;
  for (const int p : out.isolated) {
    if (!used[static_cast<std::size_t>(p)]) {
      used[static_cast<std::size_t>(p)] = 1;
      points.push_back(p);
    }
  }
  out.isolated = std::move(points);
  return out;
}

}  // namespace mk
