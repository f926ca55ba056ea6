// Boost.Geometry as a back end of the harness: bg::intersection, union_, difference and
// sym_difference of multi_polygons of point_xy<double>, after bg::correct (closing and
// orienting rings, as its documentation asks of users). [BRIEF §6] (Boost.Geometry 1.74)
// Preconditions: see peers.hpp.
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/version.hpp>

#include <string>

#include "experiments/peers/peers.hpp"

namespace mk::experiments {

namespace bg = boost::geometry;

namespace {

using BgPoint = bg::model::d2::point_xy<double>;
using BgPolygon = bg::model::polygon<BgPoint, false, true>;  // counterclockwise, closed
using BgMultiPolygon = bg::model::multi_polygon<BgPolygon>;

void append_closed(const Ring& r, BgPolygon::ring_type& out) {
  for (const Point& p : r) out.emplace_back(p.x, p.y);
  if (!r.empty()) out.emplace_back(r.front().x, r.front().y);
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

Ring from_boost(const BgPolygon::ring_type& r) {
  Ring out;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) out.push_back({bg::get<0>(r[i]), bg::get<1>(r[i])});
  return out;
}

}  // namespace

PeerOutput boost_overlay(const MultiPolygon& a, const MultiPolygon& b, Operation op) {
  const BgMultiPolygon ba = to_boost(a), bb = to_boost(b);
  BgMultiPolygon r;
  try {
    switch (op) {
      case Operation::intersection: bg::intersection(ba, bb, r); break;
      case Operation::union_: bg::union_(ba, bb, r); break;
      case Operation::difference: bg::difference(ba, bb, r); break;
      case Operation::symmetric_difference: bg::sym_difference(ba, bb, r); break;
    }
  } catch (const bg::exception& e) {
    throw PeerException(std::string("Boost.Geometry: ") + e.what());
  }
  PeerOutput out;
  for (const auto& p : r) {
    OgcPolygon q;
    q.shell = from_boost(p.outer());
    for (const auto& h : p.inners()) q.holes.push_back(from_boost(h));
    out.polygons.push_back(std::move(q));
  }
  return out;
}

std::string boost_version() {
  return "Boost " + std::to_string(BOOST_VERSION / 100000) + "." + std::to_string(BOOST_VERSION / 100 % 1000) + "." +
         std::to_string(BOOST_VERSION % 100);
}

}  // namespace mk::experiments
