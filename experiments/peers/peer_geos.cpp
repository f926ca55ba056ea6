// GEOS as a back end of the harness: GEOSIntersection_r and kin of the reentrant C API,
// which in GEOS 3.9+ run OverlayNG in floating precision (with GEOS's own fallbacks to
// snapping when that fails, as every GEOS user gets), and GEOSisValidReason_r.
// [BRIEF §6] (GEOS 3.11)
// Preconditions: see peers.hpp. Each call has its own GEOS context (runs are isolated).
#include <geos_c.h>

#include <memory>
#include <string>
#include <vector>

#include "experiments/peers/peers.hpp"

namespace mk::experiments {

namespace {

void remember_error(const char* message, void* userdata) { *static_cast<std::string*>(userdata) = message; }

// One GEOS context, its last error message, and the geometries it owns.
class Geos {
 public:
  Geos() : ctx_(GEOS_init_r()) { GEOSContext_setErrorMessageHandler_r(ctx_, remember_error, &error_); }
  ~Geos() {
    for (GEOSGeometry* g : owned_) GEOSGeom_destroy_r(ctx_, g);
    GEOS_finish_r(ctx_);
  }
  Geos(const Geos&) = delete;
  Geos& operator=(const Geos&) = delete;

  GEOSContextHandle_t ctx() const { return ctx_; }
  const std::string& error() const { return error_; }

  GEOSGeometry* own(GEOSGeometry* g) {
    if (g == nullptr) throw PeerException("GEOS: " + error_);
    owned_.push_back(g);
    return g;
  }

  // GEOS takes ownership of rings and parts passed to its constructors: those are not owned here.
  GEOSGeometry* ring(const Ring& r) {
    std::vector<double> xy;
    xy.reserve(2 * r.size() + 2);
    for (const Point& p : r) xy.insert(xy.end(), {p.x, p.y});
    if (!r.empty()) xy.insert(xy.end(), {r.front().x, r.front().y});  // GEOS rings are closed
    GEOSCoordSequence* seq = GEOSCoordSeq_copyFromBuffer_r(ctx_, xy.data(), static_cast<unsigned>(xy.size() / 2), 0, 0);
    if (seq == nullptr) throw PeerException("GEOS: " + error_);
    GEOSGeometry* g = GEOSGeom_createLinearRing_r(ctx_, seq);
    if (g == nullptr) throw PeerException("GEOS: " + error_);
    return g;
  }

  GEOSGeometry* multipolygon(const MultiPolygon& mp) {
    std::vector<GEOSGeometry*> parts;
    for (const OgcPolygon& p : mp) {
      std::vector<GEOSGeometry*> holes;
      for (const Ring& h : p.holes) holes.push_back(ring(h));
      GEOSGeometry* part = GEOSGeom_createPolygon_r(ctx_, ring(p.shell), holes.data(), static_cast<unsigned>(holes.size()));
      if (part == nullptr) throw PeerException("GEOS: " + error_);
      parts.push_back(part);
    }
    return own(GEOSGeom_createCollection_r(ctx_, GEOS_MULTIPOLYGON, parts.data(), static_cast<unsigned>(parts.size())));
  }

  Ring read_ring(const GEOSGeometry* g) {
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(ctx_, g);
    unsigned n = 0;
    GEOSCoordSeq_getSize_r(ctx_, seq, &n);
    Ring r;
    for (unsigned i = 0; i + 1 < n; ++i) {  // without the closing point
      Point p;
      GEOSCoordSeq_getXY_r(ctx_, seq, i, &p.x, &p.y);
      r.push_back(p);
    }
    return r;
  }

  // The polygonal parts of a result; lines and points are counted in `note`.
  void read(const GEOSGeometry* g, PeerOutput& out) {
    switch (GEOSGeomTypeId_r(ctx_, g)) {
      case GEOS_POLYGON: {
        if (GEOSisEmpty_r(ctx_, g) == 1) return;
        OgcPolygon p;
        p.shell = read_ring(GEOSGetExteriorRing_r(ctx_, g));
        const int holes = GEOSGetNumInteriorRings_r(ctx_, g);
        for (int i = 0; i < holes; ++i) p.holes.push_back(read_ring(GEOSGetInteriorRingN_r(ctx_, g, i)));
        out.polygons.push_back(std::move(p));
        return;
      }
      case GEOS_MULTIPOLYGON:
      case GEOS_GEOMETRYCOLLECTION: {
        const int parts = GEOSGetNumGeometries_r(ctx_, g);
        for (int i = 0; i < parts; ++i) read(GEOSGetGeometryN_r(ctx_, g, i), out);
        return;
      }
      default:
        if (GEOSisEmpty_r(ctx_, g) != 1) out.note += std::string(out.note.empty() ? "" : "; ") + "GEOS result has a " + GEOSGeomType_r(ctx_, g) + " part (not compared)";
        return;
    }
  }

 private:
  GEOSContextHandle_t ctx_;
  std::string error_;
  std::vector<GEOSGeometry*> owned_;
};

}  // namespace

PeerOutput geos_overlay(const MultiPolygon& a, const MultiPolygon& b, Operation op) {
  Geos geos;
  GEOSGeometry* ga = geos.multipolygon(a);
  GEOSGeometry* gb = geos.multipolygon(b);
  GEOSGeometry* r = nullptr;
  switch (op) {
    case Operation::intersection: r = GEOSIntersection_r(geos.ctx(), ga, gb); break;
    case Operation::union_: r = GEOSUnion_r(geos.ctx(), ga, gb); break;
    case Operation::difference: r = GEOSDifference_r(geos.ctx(), ga, gb); break;
    case Operation::symmetric_difference: r = GEOSSymDifference_r(geos.ctx(), ga, gb); break;
  }
  geos.own(r);
  PeerOutput out;
  geos.read(r, out);
  return out;
}

std::optional<bool> geos_is_valid(const MultiPolygon& polygons, std::string* why) {
  const std::optional<GeosValidityCopy> scaled = geos_validity_copy(polygons);
  if (!scaled) return std::nullopt;
  Geos geos;
  try {
    GEOSGeometry* g = geos.multipolygon(scaled->polygons);
    char* reason = GEOSisValidReason_r(geos.ctx(), g);
    if (reason == nullptr) return std::nullopt;
    const std::string text = reason;
    GEOSFree_r(geos.ctx(), reason);
    if (text == "Valid Geometry") return true;
    if (why) {
      // GEOS names a place in the scaled copy's coordinates.
      *why = text;
      if (scaled->shift != 0) *why += " (coordinates multiplied by 2^" + std::to_string(scaled->shift) + ")";
    }
    return false;
  } catch (const PeerException& e) {
    if (why) *why = e.what();
    return false;  // GEOS cannot even build it (a ring of fewer than 4 points)
  }
}

std::string geos_version() { return std::string("GEOS ") + GEOSversion(); }

}  // namespace mk::experiments
