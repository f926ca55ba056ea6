// Overlay benchmark adapter for Boost.Geometry: intersection, union_, difference and
// sym_difference of multi_polygons.
// [BRIEF §6] (Boost.Geometry 1.74 anchor)
// Preconditions: as peers.hpp. Boost.Geometry wants closed rings in the declared
// orientation; the adapter closes them and calls correct() outside the timed region.
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/version.hpp>

#include <stdexcept>
#include <string>

#include "bench/peers/peers.hpp"

namespace mk::bench {

namespace bg = boost::geometry;

namespace {

using BgPoint = bg::model::d2::point_xy<double>;
// Counterclockwise (ClockWise = false) and closed: our shells are counterclockwise already.
using BgPolygon = bg::model::polygon<BgPoint, false, true>;
using BgMultiPolygon = bg::model::multi_polygon<BgPolygon>;

void append_closed(const Ring& r, BgPolygon::ring_type& out) {
  out.reserve(r.size() + 1);
  for (const Point& p : r) out.emplace_back(p.x, p.y);
  out.emplace_back(r.front().x, r.front().y);
}

BgMultiPolygon to_boost(const MultiPolygon& mp) {
  BgMultiPolygon out;
  out.resize(mp.size());
  for (std::size_t i = 0; i < mp.size(); ++i) {
    append_closed(mp[i].shell, out[i].outer());
    for (const Ring& h : mp[i].holes) append_closed(h, out[i].inners().emplace_back());
  }
  bg::correct(out);
  return out;
}

std::size_t count_vertices(const BgMultiPolygon& mp) {
  std::size_t v = 0;
  for (const auto& p : mp) {
    v += p.outer().size() - 1;
    for (const auto& h : p.inners()) v += h.size() - 1;
  }
  return v;
}

}  // namespace

template <>
struct PeerOverlay<BoostGeometry>::Impl {
  BgMultiPolygon a, b;
};

template <>
PeerOverlay<BoostGeometry>::PeerOverlay(const MultiPolygon& a, const MultiPolygon& b)
    : impl_(std::make_unique<Impl>(Impl{to_boost(a), to_boost(b)})) {}

template <>
PeerOverlay<BoostGeometry>::~PeerOverlay() = default;

template <>
OverlayResult PeerOverlay<BoostGeometry>::run(Operation op) const {
  BgMultiPolygon r;
  try {
    switch (op) {
      case Operation::intersection: bg::intersection(impl_->a, impl_->b, r); break;
      case Operation::union_: bg::union_(impl_->a, impl_->b, r); break;
      case Operation::difference: bg::difference(impl_->a, impl_->b, r); break;
      case Operation::symmetric_difference: bg::sym_difference(impl_->a, impl_->b, r); break;
    }
  } catch (const bg::exception& e) {
    throw std::runtime_error(std::string("Boost.Geometry: ") + e.what());
  }
  return {bg::area(r), count_vertices(r)};
}

template <>
std::string PeerOverlay<BoostGeometry>::version() {
  return std::to_string(BOOST_VERSION / 100000) + "." + std::to_string(BOOST_VERSION / 100 % 1000) + "." +
         std::to_string(BOOST_VERSION % 100);
}

template class PeerOverlay<BoostGeometry>;

}  // namespace mk::bench
