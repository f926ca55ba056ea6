// WKB writer for multipolygons and Boolean results (dangling edges and isolated points as
// LineStrings and Points). [OGC06-103 §8.2] [OGC06-103 §6.1.11]
// Preconditions: finite coordinates; the result is bounded (checked, throws otherwise).
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "io/ring_rules.hpp"
#include "io/wkb.hpp"

namespace mk {

namespace {

// Little endian whatever the host: the byte order most readers expect.
template <class T>
void put(std::string& out, T value) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  }
  out.append(b, sizeof(T));
}

void put_header(std::string& out, std::uint32_t type) {
  out.push_back('\x01');
  put<std::uint32_t>(out, type);
}

void put_point(std::string& out, const Point& p) {
  put(out, p.x);
  put(out, p.y);
}

// A closed ring in the requested direction, decided exactly as in the WKT writer.
void put_ring(std::string& out, const Ring& ring, bool counterclockwise) {
  put<std::uint32_t>(out, static_cast<std::uint32_t>(ring.size() + 1));
  io_detail::visit_closed_ring(ring, counterclockwise, [&](const Point& p, bool) { put_point(out, p); });
}

void put_polygon(std::string& out, const OgcPolygon& polygon) {
  put_header(out, 3);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(1 + polygon.holes.size()));
  put_ring(out, polygon.shell, true);
  for (const Ring& hole : polygon.holes) put_ring(out, hole, false);
}

void put_polygons(std::string& out, const MultiPolygon& polygons) {
  if (polygons.size() == 1) {
    put_polygon(out, polygons.front());
    return;
  }
  put_header(out, 6);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(polygons.size()));
  for (const auto& p : polygons) put_polygon(out, p);
}

}  // namespace

std::string write_wkb(const MultiPolygon& polygons) {
  std::string out;
  if (polygons.empty()) {
    put_header(out, 3);
    put<std::uint32_t>(out, 0);
    return out;
  }
  put_polygons(out, polygons);
  return out;
}

std::string write_wkb(const Output& output) {
  if (output.unbounded) {
    throw InvalidInput("the result is unbounded (hole type) and cannot be written as WKB; use --format json");
  }
  if (output.dangling_edges.empty() && output.isolated_points.empty()) return write_wkb(output.polygons);
  std::string out;
  put_header(out, 7);
  const std::size_t parts =
      (output.polygons.empty() ? 0 : 1) + output.dangling_edges.size() + output.isolated_points.size();
  put<std::uint32_t>(out, static_cast<std::uint32_t>(parts));
  if (!output.polygons.empty()) put_polygons(out, output.polygons);
  for (const auto& [a, b] : output.dangling_edges) {
    put_header(out, 2);
    put<std::uint32_t>(out, 2);
    put_point(out, a);
    put_point(out, b);
  }
  for (const Point& p : output.isolated_points) {
    put_header(out, 1);
    put_point(out, p);
  }
  return out;
}

}  // namespace mk
