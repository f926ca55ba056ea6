// The peer libraries as back ends of the harness: GEOS (OverlayNG through the C API),
// Boost.Geometry (double), Clipper 6.4 (64-bit integers) and CGAL's
// Boolean_set_operations_2 with Epeck, each computing one regular operation on a case's
// two inputs as a user of that library would. [BRIEF §6] (the peers) [MK89 §2.3]
// Preconditions: inputs are island-type polygons given as OGC polygons-with-holes
// (run_peer throws PeerUnsupported otherwise, except for CGAL, which also takes any
// polygon of the paper's model through its complement); regular operations only.
#pragma once

#include <gmpxx.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/polygon.hpp"

namespace mk::experiments {

// A case's input as the peers take it: the paper's model and, when it has one, its OGC
// structure (shells and the holes directly inside them) exactly as the case gives it.
struct PeerInput {
  const Polygon* polygon = nullptr;
  const MultiPolygon* ogc = nullptr;  // null: no OGC form (hole-type, or rings that do not nest)
};

// What a peer returns: polygons-with-holes of doubles (its own orientation and ring
// start), and for CGAL the exact rational rings as well (`exact_rings`, shells then holes,
// same order as `polygons`). `unbounded`: CGAL's result is unbounded; `polygons` then holds
// the complement's polygons.
struct PeerOutput {
  MultiPolygon polygons;
  std::vector<std::vector<std::vector<RationalPoint>>> exact_rings;  // per polygon: shell, holes
  bool is_exact = false;  // CGAL: exact_rings are the result, `polygons` only its rounding
  bool unbounded = false;
  double grid = 0;        // Clipper: the spacing of its integer grid in input units (1 / scale)
  std::string note;       // parts of the result the comparison does not see (lines, points)
};

// The library threw or reported an error (GEOS TopologyException, Boost.Geometry
// overlay_invalid_input_exception, CGAL precondition, Clipper's Execute returning false).
struct PeerException : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// The peer cannot express this input (hole-type polygon for an OGC library).
struct PeerUnsupported : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Peers built into this binary, in a fixed order: geos, boost, clipper, cgal_epeck.
std::vector<std::string_view> peer_names();
bool is_peer(std::string_view name);

// One regular operation. Throws PeerException, PeerUnsupported, or std::invalid_argument
// for an unknown name.
PeerOutput run_peer(std::string_view name, const PeerInput& a, const PeerInput& b, Operation op);

// GEOS's isValid (OGC validity) of polygons, asked about their copy scaled exactly by the
// power of two that brings the largest coordinate magnitude into [1, 2): GEOS's orientation
// tests multiply coordinate differences, which underflow for ulp-wide features at 1e-150 (and
// overflow near 1e300), and then report crossings that are not there; scaled, the question
// is the same and GEOS's arithmetic stays in range. Empty when GEOS is not built in, when a
// coordinate is not finite, or when a nonzero coordinate of the scaled copy is below 2^-400
// (a spread too wide for GEOS's products: its verdict would be about its arithmetic). `why`
// receives GEOS's reason when invalid.
std::optional<bool> geos_is_valid(const MultiPolygon& polygons, std::string* why = nullptr);

// The copy of `polygons` that geos_is_valid asks GEOS about, every coordinate multiplied by
// 2^shift, or empty when it asks nothing (see there).
struct GeosValidityCopy {
  MultiPolygon polygons;
  int shift = 0;
};
std::optional<GeosValidityCopy> geos_validity_copy(const MultiPolygon& polygons);

// "GEOS 3.11.1-CAPI-1.17.1", "Boost 1.74.0", ...: one line per peer library built in.
std::vector<std::string> peer_versions();

// Per-library back ends (peer_*.cpp), each built only when its library is found.
PeerOutput geos_overlay(const MultiPolygon& a, const MultiPolygon& b, Operation op);
PeerOutput boost_overlay(const MultiPolygon& a, const MultiPolygon& b, Operation op);
PeerOutput clipper_overlay(const MultiPolygon& a, const MultiPolygon& b, Operation op);
PeerOutput cgal_overlay(const PeerInput& a, const PeerInput& b, Operation op);
std::string geos_version();
std::string boost_version();
std::string clipper_version();
std::string cgal_version();

}  // namespace mk::experiments
