// GeoJSON writer for multipolygons and Boolean results, following the right-hand rule.
// [RFC7946 §3.1.6] [RFC7946 §3.1.8] (GeometryCollection for dangling edges and points)
// Preconditions: finite coordinates; the result is bounded (checked, throws otherwise).
#include <string>

#include "core/error.hpp"
#include "io/collection.hpp"
#include "io/geojson.hpp"
#include "io/ring_rules.hpp"
#include "io/text_util.hpp"

namespace mk {

namespace {

using io_detail::append_double;

void append_position(std::string& out, const Point& p) {
  out.push_back('[');
  append_double(out, p.x);
  out.push_back(',');
  append_double(out, p.y);
  out.push_back(']');
}

// A closed ring; shells counterclockwise and holes clockwise, decided exactly.
void append_ring(std::string& out, const Ring& ring, bool counterclockwise) {
  out.push_back('[');
  io_detail::visit_closed_ring(ring, counterclockwise, [&](const Point& p, bool is_first) {
    if (!is_first) out.push_back(',');
    append_position(out, p);
  });
  out.push_back(']');
}

void append_polygon_coordinates(std::string& out, const OgcPolygon& polygon) {
  out.push_back('[');
  append_ring(out, polygon.shell, true);
  for (const Ring& hole : polygon.holes) {
    out.push_back(',');
    append_ring(out, hole, false);
  }
  out.push_back(']');
}

void append_polygons(std::string& out, const MultiPolygon& polygons) {
  if (polygons.size() <= 1) {
    out += R"({"type":"Polygon","coordinates":)";
    if (polygons.empty()) {
      out += "[]";
    } else {
      append_polygon_coordinates(out, polygons.front());
    }
    out.push_back('}');
    return;
  }
  out += R"({"type":"MultiPolygon","coordinates":[)";
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (i > 0) out.push_back(',');
    append_polygon_coordinates(out, polygons[i]);
  }
  out += "]}";
}

}  // namespace

std::string write_geojson(const MultiPolygon& polygons) {
  std::string out;
  append_polygons(out, polygons);
  return out;
}

std::string write_geojson(const Output& output) {
  if (output.unbounded) {
    throw InvalidInput(
        "the result is unbounded (hole type) and cannot be written as GeoJSON; use --format "
        "json");
  }
  if (output.dangling_edges.empty() && output.isolated_points.empty()) {
    return write_geojson(output.polygons);
  }
  std::string out = R"({"type":"GeometryCollection","geometries":[)";
  io_detail::for_each_member(
      output, [&] { out.push_back(','); }, [&](const MultiPolygon& polygons) { append_polygons(out, polygons); },
      [&](const Point& a, const Point& b) {
        out += R"({"type":"LineString","coordinates":[)";
        append_position(out, a);
        out.push_back(',');
        append_position(out, b);
        out += "]}";
      },
      [&](const Point& p) {
        out += R"({"type":"Point","coordinates":)";
        append_position(out, p);
        out.push_back('}');
      });
  out += "]}";
  return out;
}

}  // namespace mk
