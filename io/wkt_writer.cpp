// WKT writer for multipolygons and Boolean results (with dangling edges and isolated
// points as LINESTRINGs and POINTs). [OGC06-103 §7] [OGC06-103 §6.1.11]
// Preconditions: finite coordinates; the result is bounded (checked, throws otherwise).
#include <string>

#include "core/error.hpp"
#include "io/ring_rules.hpp"
#include "io/text_util.hpp"
#include "io/wkt.hpp"

namespace mk {

namespace {

using io_detail::append_double;

void append_point(std::string& out, const Point& p) {
  append_double(out, p.x);
  out.push_back(' ');
  append_double(out, p.y);
}

// A closed ring in the requested direction. The direction is decided exactly, so a
// needle-thin shell is never written clockwise.
void append_ring(std::string& out, const Ring& ring, bool counterclockwise) {
  out.push_back('(');
  io_detail::visit_closed_ring(ring, counterclockwise, [&](const Point& p, bool is_first) {
    if (!is_first) out += ", ";
    append_point(out, p);
  });
  out.push_back(')');
}

void append_polygon_text(std::string& out, const OgcPolygon& polygon) {
  out.push_back('(');
  append_ring(out, polygon.shell, true);
  for (const Ring& hole : polygon.holes) {
    out += ", ";
    append_ring(out, hole, false);
  }
  out.push_back(')');
}

// POLYGON, MULTIPOLYGON or nothing (for an empty multipolygon inside a collection).
void append_polygons(std::string& out, const MultiPolygon& polygons) {
  if (polygons.size() == 1) {
    out += "POLYGON ";
    append_polygon_text(out, polygons.front());
    return;
  }
  out += "MULTIPOLYGON (";
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (i > 0) out += ", ";
    append_polygon_text(out, polygons[i]);
  }
  out.push_back(')');
}

}  // namespace

std::string write_wkt(const MultiPolygon& polygons) {
  if (polygons.empty()) return "POLYGON EMPTY";
  std::string out;
  append_polygons(out, polygons);
  return out;
}

std::string write_wkt(const Output& output) {
  if (output.unbounded) {
    throw InvalidInput(
        "the result is unbounded (hole type) and cannot be written as WKT; use --format json");
  }
  if (output.dangling_edges.empty() && output.isolated_points.empty()) {
    return write_wkt(output.polygons);
  }
  std::string out = "GEOMETRYCOLLECTION (";
  bool first = true;
  const auto separate = [&] {
    if (!first) out += ", ";
    first = false;
  };
  if (!output.polygons.empty()) {
    separate();
    append_polygons(out, output.polygons);
  }
  for (const auto& [a, b] : output.dangling_edges) {
    separate();
    out += "LINESTRING (";
    append_point(out, a);
    out += ", ";
    append_point(out, b);
    out.push_back(')');
  }
  for (const Point& p : output.isolated_points) {
    separate();
    out += "POINT (";
    append_point(out, p);
    out.push_back(')');
  }
  out.push_back(')');
  return out;
}

}  // namespace mk
