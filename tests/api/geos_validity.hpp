// GEOS's own verdict on written polygons (GEOSisValid_r): a check of the output independent
// of mkbool's exact one, and the rules users meet downstream (shapely, PostGIS). Shared by
// the certified-rounding tests. [BRIEF §6a] (valid in OGC's sense as GEOS checks it)
// Preconditions: built with GEOS (MK_HAVE_GEOS); the polygons' rings are open (first point
// not repeated), as mk::Output writes them.
#pragma once

#include <geos_c.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/polygon.hpp"

namespace mk::test {

class Geos {
 public:
  Geos() : h_(GEOS_init_r()) {}
  ~Geos() { GEOS_finish_r(h_); }
  Geos(const Geos&) = delete;
  Geos& operator=(const Geos&) = delete;
  // scale: every coordinate multiplied by it (a power of two: exact, so validity is kept).
  bool is_valid(const MultiPolygon& mp, std::string* why, double scale = 1) {
    scale_ = scale;
    std::vector<GEOSGeometry*> parts;
    for (const auto& p : mp) {
      GEOSGeometry* shell = ring(p.shell);
      std::vector<GEOSGeometry*> holes;
      for (const auto& h : p.holes) holes.push_back(ring(h));
      parts.push_back(GEOSGeom_createPolygon_r(h_, shell, holes.data(), static_cast<unsigned>(holes.size())));
    }
    GEOSGeometry* g = GEOSGeom_createCollection_r(h_, GEOS_MULTIPOLYGON, parts.data(), static_cast<unsigned>(parts.size()));
    const char valid = GEOSisValid_r(h_, g);
    if (valid != 1 && why) {
      char* reason = GEOSisValidReason_r(h_, g);
      *why = reason;
      GEOSFree_r(h_, reason);
    }
    GEOSGeom_destroy_r(h_, g);
    return valid == 1;
  }

 private:
  GEOSGeometry* ring(const Ring& r) {
    GEOSCoordSequence* s = GEOSCoordSeq_create_r(h_, static_cast<unsigned>(r.size() + 1), 2);
    for (std::size_t i = 0; i <= r.size(); ++i) {
      const Point& p = r[i % r.size()];
      GEOSCoordSeq_setXY_r(h_, s, static_cast<unsigned>(i), p.x * scale_, p.y * scale_);
    }
    return GEOSGeom_createLinearRing_r(h_, s);
  }
  GEOSContextHandle_t h_;
  double scale_ = 1;
};

// The power of two that brings the largest coordinate magnitude into [1, 2): GEOS's
// orientation test multiplies coordinate differences, which underflow for coordinates
// near 1e-150 whose differences are a few ulps, and then reports crossings that are not
// there; scaled exactly, the question is the same and GEOS answers it in range.
inline double unit_scale(const MultiPolygon& mp) {
  double largest = 0;
  for (const auto& p : mp) {
    for (const Point& q : p.shell) largest = std::max({largest, std::fabs(q.x), std::fabs(q.y)});
  }
  return largest > 0 ? std::ldexp(1.0, -std::ilogb(largest)) : 1.0;
}

// Whether every nonzero coordinate lies between 1e-200 and 1e200 in magnitude: where GEOS's
// products of coordinate differences can decide (issue 12 asks GEOS there).
inline bool in_geos_range(const MultiPolygon& mp) {
  const auto fits = [](double v) { return v == 0 || (std::fabs(v) >= 1e-200 && std::fabs(v) <= 1e200); };
  const auto ring_fits = [&](const Ring& r) {
    return std::all_of(r.begin(), r.end(), [&](const Point& q) { return fits(q.x) && fits(q.y); });
  };
  return std::all_of(mp.begin(), mp.end(), [&](const OgcPolygon& p) {
    return ring_fits(p.shell) && std::all_of(p.holes.begin(), p.holes.end(), ring_fits);
  });
}

}  // namespace mk::test
