// The registry of peer back ends: which libraries this binary was built with, and the
// dispatch of one run to its adapter. [BRIEF §6]
// Preconditions: see peers.hpp. MK_HAVE_<LIBRARY> says which adapters are compiled in.
#include "experiments/peers/peers.hpp"

#include <algorithm>
#include <cmath>

namespace mk::experiments {

std::vector<std::string_view> peer_names() {
  std::vector<std::string_view> out;
#ifdef MK_HAVE_GEOS
  out.push_back("geos");
#endif
#ifdef MK_HAVE_BOOST_GEOMETRY
  out.push_back("boost");
#endif
#ifdef MK_HAVE_CLIPPER
  out.push_back("clipper");
#endif
#ifdef MK_HAVE_CGAL
  out.push_back("cgal_epeck");
#endif
  return out;
}

bool is_peer(std::string_view name) {
  for (const auto p : peer_names()) {
    if (p == name) return true;
  }
  return false;
}

PeerOutput run_peer(std::string_view name, const PeerInput& a, const PeerInput& b, Operation op) {
  if (!is_peer(name)) throw std::invalid_argument("peer '" + std::string(name) + "' is not built into this binary");
  if (name == "cgal_epeck") {
#ifdef MK_HAVE_CGAL
    return cgal_overlay(a, b, op);
#endif
  }
  if (a.ogc == nullptr || b.ogc == nullptr || a.polygon->type != PolygonType::island || b.polygon->type != PolygonType::island) {
    throw PeerUnsupported(std::string(name) + ": the input has no OGC form (hole-type polygon or rings that do not nest)");
  }
#ifdef MK_HAVE_GEOS
  if (name == "geos") return geos_overlay(*a.ogc, *b.ogc, op);
#endif
#ifdef MK_HAVE_BOOST_GEOMETRY
  if (name == "boost") return boost_overlay(*a.ogc, *b.ogc, op);
#endif
#ifdef MK_HAVE_CLIPPER
  if (name == "clipper") return clipper_overlay(*a.ogc, *b.ogc, op);
#endif
  throw std::invalid_argument("peer '" + std::string(name) + "' is not built into this binary");
}

std::vector<std::string> peer_versions() {
  std::vector<std::string> out;
#ifdef MK_HAVE_GEOS
  out.push_back(geos_version());
#endif
#ifdef MK_HAVE_BOOST_GEOMETRY
  out.push_back(boost_version());
#endif
#ifdef MK_HAVE_CLIPPER
  out.push_back(clipper_version());
#endif
#ifdef MK_HAVE_CGAL
  out.push_back(cgal_version());
#endif
  return out;
}

std::optional<GeosValidityCopy> geos_validity_copy(const MultiPolygon& polygons) {
  const auto for_each_coordinate = [&](auto&& f) {
    for (const OgcPolygon& p : polygons) {
      for (const Point& q : p.shell) f(q.x), f(q.y);
      for (const Ring& h : p.holes) {
        for (const Point& q : h) f(q.x), f(q.y);
      }
    }
  };
  double largest = 0;
  bool finite = true;
  for_each_coordinate([&](double v) {
    finite = finite && std::isfinite(v);
    largest = std::max(largest, std::fabs(v));
  });
  if (!finite) return std::nullopt;
  // 2^shift brings `largest` into [1, 2); every scaled coordinate that is not 0 is at least
  // 2^-400 (checked), so each is a normal double and the scaling exact.
  const int shift = largest > 0 ? -std::ilogb(largest) : 0;
  bool in_range = true;
  for_each_coordinate([&](double v) { in_range = in_range && (v == 0 || std::fabs(std::ldexp(v, shift)) >= 0x1p-400); });
  if (!in_range) return std::nullopt;
  GeosValidityCopy copy{polygons, shift};
  const auto scale = [&](Ring& r) {
    for (Point& q : r) q = {std::ldexp(q.x, shift), std::ldexp(q.y, shift)};
  };
  for (OgcPolygon& p : copy.polygons) {
    scale(p.shell);
    for (Ring& h : p.holes) scale(h);
  }
  return copy;
}

#ifndef MK_HAVE_GEOS
std::optional<bool> geos_is_valid(const MultiPolygon&, std::string*) { return std::nullopt; }
#endif

}  // namespace mk::experiments
