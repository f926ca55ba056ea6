// Adapters of the peer libraries for the overlay benchmark: GEOS (C API), Boost.Geometry,
// Clipper 6.4 and CGAL's Boolean_set_operations_2 with Epeck, each computing one operation
// on a workload's two inputs.
// [BRIEF §6] (the peers and their anchor times)
// Preconditions: inputs are OGC polygons-with-holes with shells counterclockwise and holes
// clockwise, rings not closed, parts of one multipolygon meeting at most at vertices.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "core/polygon.hpp"

namespace mk::bench {

// What the benchmark reads from a peer's result: its area and its size. `vertices` counts
// ring vertices without the closing repeat (and the points of lines or points, if a peer
// returns them).
struct OverlayResult {
  double area = 0;
  std::size_t vertices = 0;
};

// The peer libraries, as tags: BM_Overlay<Geos> and so on.
struct Geos {  // GEOS through its reentrant C API: OverlayNG in floating precision
  static constexpr std::string_view name = "GEOS";
};
struct BoostGeometry {  // model::multi_polygon of counterclockwise closed polygons of point_xy<double>
  static constexpr std::string_view name = "BoostGeometry";
};
struct Clipper {  // Clipper 6.4 on 64-bit integers: coordinates scaled by a power of two
  static constexpr std::string_view name = "Clipper";
};
struct ClipperPolyTree {  // the same, its result as a PolyTree: holes assigned to their outer rings
  static constexpr std::string_view name = "ClipperPolyTree";
};
struct CgalEpeck {  // Polygon_set_2 over Exact_predicates_exact_constructions_kernel
  static constexpr std::string_view name = "CgalEpeck";
};

// One library's copy of a workload's two inputs. The constructor converts them to the
// library's own types, outside the benchmark's timed region; run() is the timed part: the
// operation, the area of its result and freeing it. run() throws std::runtime_error when
// the library reports an error. Each library's adapter is its own .cpp file, built only
// when the library is found (MK_HAVE_<LIBRARY>).
template <class Library>
class PeerOverlay {
 public:
  PeerOverlay(const MultiPolygon& a, const MultiPolygon& b);
  ~PeerOverlay();
  PeerOverlay(const PeerOverlay&) = delete;
  PeerOverlay& operator=(const PeerOverlay&) = delete;
  OverlayResult run(Operation op) const;
  static std::string version();  // the library's version, for the benchmark's context

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mk::bench
