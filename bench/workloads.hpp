// Benchmark workloads: pairs of input polygons generated from a fixed seed (blob, star,
// stripes, three checkerboards, many holes, long spikes, nested squares), for the benchmark
// against peers: each stresses one way for a Boolean operation to turn superlinear.
// [MK89 §4.3] (cost of the intersection step as n and k grow) [BRIEF §6] (blob, star)
// Preconditions: n >= 3 for blob, star and long spikes, n >= 1 for the others.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/polygon.hpp"

namespace mk::bench {

enum class WorkloadKind : std::uint8_t {
  blob,
  star,
  stripes,
  checkerboard,
  checkerboard_shared,
  checkerboard_offset,
  many_holes,
  long_spikes,
  nested_squares,
  nested_wavy_rings
};

constexpr std::string_view workload_name(WorkloadKind w) {
  switch (w) {
    case WorkloadKind::blob: return "blob";
    case WorkloadKind::star: return "star";
    case WorkloadKind::stripes: return "stripes";
    case WorkloadKind::checkerboard: return "checkerboard";
    case WorkloadKind::checkerboard_shared: return "checkerboard_shared";
    case WorkloadKind::checkerboard_offset: return "checkerboard_offset";
    case WorkloadKind::many_holes: return "many_holes";
    case WorkloadKind::long_spikes: return "long_spikes";
    case WorkloadKind::nested_squares: return "nested_squares";
    case WorkloadKind::nested_wavy_rings: return "nested_wavy_rings";
  }
  return "?";
}

inline constexpr std::array<WorkloadKind, 10> all_workload_kinds{
    WorkloadKind::blob,       WorkloadKind::star,        WorkloadKind::stripes,
    WorkloadKind::checkerboard, WorkloadKind::checkerboard_shared, WorkloadKind::checkerboard_offset,
    WorkloadKind::many_holes, WorkloadKind::long_spikes, WorkloadKind::nested_squares,
    WorkloadKind::nested_wavy_rings};

// The kind whose workload_name is `name`, if any.
constexpr std::optional<WorkloadKind> workload_named(std::string_view name) {
  for (const WorkloadKind k : all_workload_kinds) {
    if (workload_name(k) == name) return k;
  }
  return std::nullopt;
}

// Two inputs in both forms the benchmark needs: OGC polygons-with-holes (shells counter-
// clockwise, holes clockwise, rings not closed) for the peers, and the paper's model (one
// island-type polygon holding every ring) for mkbool.
struct Workload {
  WorkloadKind kind = WorkloadKind::blob;
  std::size_t n = 0;  // the size argument: see each generator
  std::uint64_t seed = 0;
  MultiPolygon a_ogc, b_ogc;
  Polygon a, b;
  std::size_t vertices() const;  // vertices of A plus vertices of B
};

// Two smooth closed curves r(t) = 100 (1 + 0.1 sin(5t + seed)) of n vertices each, the same
// shape around centres (0, 0) and (30, 10). With seed 0 they cross twice (some other seeds
// cross four times: the curve is not convex).
Workload blob(std::size_t n, std::uint64_t seed = 0);

// Two star-shaped polygons of n vertices each around the same centres as blob: sorted
// random angles, radii uniform in [50, 100]; about n^2 / 400 crossings.
Workload star(std::size_t n, std::uint64_t seed = 1);

// n full-width stripes per polygon, interleaved without touching: A's are [0, 4n] x [4i, 4i + 1],
// B's [0, 4n] x [4i + 2, 4i + 3]. No crossing at all; every stripe overlaps every other in x.
Workload stripes(std::size_t n);

// Two checkerboards of n unit squares each (the dark cells of a square grid, touching their
// diagonal neighbours at corners), B shifted by half a cell along x: collinear overlapping
// edges of both directions and vertex_on_edge everywhere, no proper crossing.
Workload checkerboard(std::size_t n);

// The n dark cells of a grid against the n light cells of the same grid: every edge of B is
// an edge of A (shared_edge everywhere), the regions only touch.
Workload checkerboard_shared(std::size_t n);

// The n dark cells of a grid against the same cells shifted by half a cell along x and y:
// every square of B crosses two of A (proper crossings, about 4 per square).
Workload checkerboard_offset(std::size_t n);

// A square with a k x k grid of square holes (k = ceil(sqrt(n))), against the same shifted by
// a fifth of a cell along x and y: their union is one polygon with k^2 small holes (where
// the holes of A and B overlap).
Workload many_holes(std::size_t n);

// A saw whose n / 2 edges each span the whole width of the box (2 n / 4 teeth), against a
// smooth closed curve of n / 2 vertices inside the box: long edges over a fine polygon,
// about n crossings.
Workload long_spikes(std::size_t n);

// n concentric square annuli per polygon: A between half-sizes 4k+1 and 4k+3, B between 4k+2
// and 4k+5 (k = 0..n-1). Each annulus of B overlaps one of A and touches the next one along
// the whole of its outer square (collinear edges of opposite direction, shared corners).
Workload nested_squares(std::size_t n);
// Contour lines: n annuli per polygon, each between two wavy 64-point rings around one
// centre (B's moved by (0.7, 0.3)); outside, a ring's segments are far longer than the
// spacing of the rings, so that boxes of segments and of chains overlap many they never
// meet.
Workload nested_wavy_rings(std::size_t n);

Workload make_workload(WorkloadKind kind, std::size_t n);

}  // namespace mk::bench
