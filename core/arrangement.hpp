// The data the six steps share: input points with identities, prepared polygons (cycles),
// the vertex rings AV and BV as edges with inserted points, and their edge fragments.
// [MK89 §3.3] (vertex rings AV, BV) [MK89 §2.2] (irreducible parts)
// Preconditions: filled in order by prepare, normalize_orientations, insert_intersections,
// classify_fragments.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "kernel/kernel.hpp"
#include "core/polygon.hpp"

namespace mk {

// An original edge of a prepared polygon, src -> dst (point ids). The vertices step 3
// inserts strictly inside it are known through its fragments (Fragment::edge).
struct Edge {
  int src = -1;
  int dst = -1;
};

// An edge fragment [MK89 §3.1 step 4]: the piece of `edge` between two consecutive vertices
// of a vertex ring. far_left[i] / far_right[i] are the winding depths of polygon i (0 = A,
// 1 = B) just left and right of it, counted with FAR(i) positive [MK89 §2.2].
struct Fragment {
  int from = -1;
  int to = -1;
  int edge = -1;
  std::array<int, 2> far_left{};
  std::array<int, 2> far_right{};
};

// Where a cycle came from in the user's input, for error messages.
struct CycleOrigin {
  int ring = -1;
  int vertex = -1;
};

// One input polygon made vertex-complete and split into irreducible cycles [MK89 §2.2].
struct PreparedPolygon {
  PolygonType type = PolygonType::island;
  std::vector<std::vector<int>> cycles;  // point ids, 2+ distinct vertices each
  std::vector<CycleOrigin> origins;      // per cycle
  std::vector<int> point_cycles;         // one-sided polygons: a single point id each
  // Table 1: +1 when FAR(P) lies left of every edge, -1 after B was turned against A.
  int far_sign = 1;
  // The vertex ring [MK89 §3.3]: edges cycle after cycle, and their fragments.
  std::vector<Edge> edges;
  std::vector<int> cycle_first_edge;  // size cycles + 1
  std::vector<Fragment> fragments;
  std::vector<int> cycle_first_fragment;  // size cycles + 1
};

// The key of an undirected segment between two vertex ids.
inline std::uint64_t segment_key(int u, int w) {
  const auto lo = static_cast<std::uint64_t>(static_cast<std::uint32_t>(u < w ? u : w));
  const auto hi = static_cast<std::uint64_t>(static_cast<std::uint32_t>(u < w ? w : u));
  return (lo << 32) | hi;
}

// The crossings and touching points between A and B that the preparation's pair search
// found, searching both polygons at once (prepare.hpp), for step 3 to use instead of a search
// of its own when every ring stayed as it was: nothing inserted, each ring one cycle. Edges
// are numbered polygon by polygon, ring after ring in input order (rings of one point have
// none), as the rings ran in the input; a cycle's first point tells step 3 whether step 1
// turned it.
template <class Vertex>
struct EarlyIntersections {
  struct Crossing {
    int a, b;  // edge numbers in A and B
    Vertex vertex;
  };
  struct Part {  // what one part of the search found, in its order
    std::vector<Crossing> crossings;
    std::array<std::vector<std::pair<int, int>>, 2> inserted;  // per polygon: (edge number, point id)
  };
  bool found = false;
  std::vector<Part> parts;
  std::array<std::vector<int>, 2> ring_start;  // per polygon, per cycle: its first point as input
};

// What step 3 proved of the arrangement for the rounding certificate (separation_rules.hpp):
// when `threshold` T is positive, along every input edge consecutive vertices are more than
// T apart, and each crossing's or ring corner's neighbours more than T from its other edge,
// for every crossing's box extent at most `half_size_bound` R (T above 4R).
struct Separation {
  double threshold = 0;
  double half_size_bound = 0;
};

template <Kernel K>
struct Arrangement {
  // Input points of A and B, deduplicated; the id of a point is its index, and ids follow
  // lexicographic (x, y) order, so comparing ids compares points.
  std::vector<typename K::Point> points;
  // Rank of each input point's x among the distinct x values (non-decreasing in the id).
  std::vector<int> x_rank;
  // The proper crossings: vertex id num_points() + i is crossings[i].
  std::vector<typename K::Vertex> crossings;
  std::array<PreparedPolygon, 2> polygon;
  // Step 3's findings made while preparing, when they hold (see EarlyIntersections).
  EarlyIntersections<typename K::Vertex> early;
  // Step 3's proof of rules N and C, when it made one.
  Separation separation;

  int num_points() const { return static_cast<int>(points.size()); }
  bool is_input_point(int id) const { return id < num_points(); }
  int num_crossings() const { return static_cast<int>(crossings.size()); }
  int num_vertices() const { return num_points() + num_crossings(); }
  // Asks the processor to fetch a crossing's storage (both ends of it: a vertex may straddle
  // cache lines) before vertex(id) reads it; nothing for input points.
  void prefetch(int id) const {
    if (id < num_points()) return;
    const auto* at = reinterpret_cast<const char*>(&crossings[static_cast<std::size_t>(id - num_points())]);
    __builtin_prefetch(at);
    __builtin_prefetch(at + sizeof(typename K::Vertex) - 1);
  }
  // Any vertex by id: input points are made on demand, so they are stored only once.
  typename K::Vertex vertex(int id) const {
    return id < num_points() ? K::vertex(points[id]) : crossings[id - num_points()];
  }
};

// Frees the edges and fragments of both polygons (what steps 2-5 built), keeping the points,
// the crossings and the cycles.
template <Kernel K>
void release_fragments(Arrangement<K>& arr) {
  for (PreparedPolygon& p : arr.polygon) {
    std::vector<Edge>().swap(p.edges);
    std::vector<int>().swap(p.cycle_first_edge);
    std::vector<Fragment>().swap(p.fragments);
    std::vector<int>().swap(p.cycle_first_fragment);
  }
}

}  // namespace mk
