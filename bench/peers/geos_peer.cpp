// Overlay benchmark adapter for GEOS: the reentrant C API (GEOSIntersection_r and kin).
// [BRIEF §6] (GEOS 3.11 anchor)
// Preconditions: as peers.hpp; GEOS's default floating precision model, so crossing
// points are rounded to doubles by GEOS.
#include <geos_c.h>

#include <cstdarg>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/peers/peers.hpp"

namespace mk::bench {

namespace {

// GEOS reports errors through a callback; the last message becomes the exception text.
void remember_error(const char* message, void* userdata) { *static_cast<std::string*>(userdata) = message; }

}  // namespace

template <>
struct PeerOverlay<Geos>::Impl {
  GEOSContextHandle_t ctx = GEOS_init_r();
  std::string error;
  GEOSGeometry* a = nullptr;
  GEOSGeometry* b = nullptr;

  Impl() { GEOSContext_setErrorMessageHandler_r(ctx, remember_error, &error); }
  ~Impl() {
    if (a) GEOSGeom_destroy_r(ctx, a);
    if (b) GEOSGeom_destroy_r(ctx, b);
    GEOS_finish_r(ctx);
  }

  GEOSGeometry* checked(GEOSGeometry* g) const {
    if (!g) throw std::runtime_error("GEOS: " + error);
    return g;
  }

  // GEOS rings are closed: the first point is repeated at the end.
  GEOSGeometry* linear_ring(const Ring& r) const {
    std::vector<double> xy;
    xy.reserve(2 * r.size() + 2);
    for (const Point& p : r) xy.insert(xy.end(), {p.x, p.y});
    xy.insert(xy.end(), {r.front().x, r.front().y});
    GEOSCoordSequence* seq =
        GEOSCoordSeq_copyFromBuffer_r(ctx, xy.data(), static_cast<unsigned>(r.size() + 1), 0, 0);
    return checked(GEOSGeom_createLinearRing_r(ctx, checked_seq(seq)));
  }
  GEOSCoordSequence* checked_seq(GEOSCoordSequence* s) const {
    if (!s) throw std::runtime_error("GEOS: " + error);
    return s;
  }

  GEOSGeometry* multipolygon(const MultiPolygon& mp) const {
    std::vector<GEOSGeometry*> parts;
    for (const OgcPolygon& p : mp) {
      std::vector<GEOSGeometry*> holes;
      for (const Ring& h : p.holes) holes.push_back(linear_ring(h));
      parts.push_back(checked(GEOSGeom_createPolygon_r(ctx, linear_ring(p.shell), holes.data(),
                                                       static_cast<unsigned>(holes.size()))));
    }
    return checked(GEOSGeom_createCollection_r(ctx, GEOS_MULTIPOLYGON, parts.data(),
                                               static_cast<unsigned>(parts.size())));
  }

  std::size_t vertices(const GEOSGeometry* g) const {
    switch (GEOSGeomTypeId_r(ctx, g)) {
      case GEOS_POLYGON: {
        std::size_t v = static_cast<std::size_t>(GEOSGeomGetNumPoints_r(ctx, GEOSGetExteriorRing_r(ctx, g))) - 1;
        const int holes = GEOSGetNumInteriorRings_r(ctx, g);
        for (int i = 0; i < holes; ++i) {
          v += static_cast<std::size_t>(GEOSGeomGetNumPoints_r(ctx, GEOSGetInteriorRingN_r(ctx, g, i))) - 1;
        }
        return v;
      }
      case GEOS_MULTIPOLYGON:
      case GEOS_MULTILINESTRING:
      case GEOS_MULTIPOINT:
      case GEOS_GEOMETRYCOLLECTION: {
        std::size_t v = 0;
        const int parts = GEOSGetNumGeometries_r(ctx, g);
        for (int i = 0; i < parts; ++i) v += vertices(GEOSGetGeometryN_r(ctx, g, i));
        return v;
      }
      default: return static_cast<std::size_t>(GEOSGetNumCoordinates_r(ctx, g));
    }
  }
};

template <>
PeerOverlay<Geos>::PeerOverlay(const MultiPolygon& a, const MultiPolygon& b) : impl_(std::make_unique<Impl>()) {
  impl_->a = impl_->multipolygon(a);
  impl_->b = impl_->multipolygon(b);
}

template <>
PeerOverlay<Geos>::~PeerOverlay() = default;

template <>
OverlayResult PeerOverlay<Geos>::run(Operation op) const {
  const Impl& m = *impl_;
  GEOSGeometry* r = nullptr;
  switch (op) {
    case Operation::intersection: r = GEOSIntersection_r(m.ctx, m.a, m.b); break;
    case Operation::union_: r = GEOSUnion_r(m.ctx, m.a, m.b); break;
    case Operation::difference: r = GEOSDifference_r(m.ctx, m.a, m.b); break;
    case Operation::symmetric_difference: r = GEOSSymDifference_r(m.ctx, m.a, m.b); break;
  }
  m.checked(r);
  OverlayResult out;
  const bool ok = GEOSArea_r(m.ctx, r, &out.area) == 1;
  out.vertices = m.vertices(r);
  GEOSGeom_destroy_r(m.ctx, r);
  if (!ok) throw std::runtime_error("GEOS: area: " + m.error);
  return out;
}

template <>
std::string PeerOverlay<Geos>::version() {
  return GEOSversion();
}

template class PeerOverlay<Geos>;

}  // namespace mk::bench
