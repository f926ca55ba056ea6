// WKB reader for Polygon, MultiPolygon and flat GeometryCollections of those.
// [OGC06-103 §8.2] (byte order, geometry type codes) [OGC06-103 §6.1.11] (rings)
// Preconditions: none; every malformed byte string throws mk::InvalidInput with the offset.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/ring_rules.hpp"
#include "io/wkb.hpp"

namespace mk {

namespace {

// Geometry type codes of [OGC06-103 §8.2.3] (2D; ISO adds 1000 for Z, 2000 for M, 3000
// for ZM) and PostGIS's extended flags in the type's high bits.
constexpr std::uint32_t wkb_polygon = 3;
constexpr std::uint32_t wkb_multipolygon = 6;
constexpr std::uint32_t wkb_collection = 7;
constexpr std::uint32_t ewkb_z = 0x80000000u;
constexpr std::uint32_t ewkb_m = 0x40000000u;
constexpr std::uint32_t ewkb_srid = 0x20000000u;

// A coordinate's bytes: a vertex takes 2 to 4 of them (x y, then Z and/or M), so no count
// can ask for more elements than bytes_left / (8 * coordinates).
constexpr std::size_t coordinate_bytes = 8;

std::string type_name(std::uint32_t base) {
  switch (base) {
    case 1: return "Point";
    case 2: return "LineString";
    case 3: return "Polygon";
    case 4: return "MultiPoint";
    case 5: return "MultiLineString";
    case 6: return "MultiPolygon";
    case 7: return "GeometryCollection";
    case 8: return "CircularString";
    case 9: return "CompoundCurve";
    case 10: return "CurvePolygon";
    case 11: return "MultiCurve";
    case 12: return "MultiSurface";
    case 15: return "PolyhedralSurface";
    case 16: return "TIN";
    case 17: return "Triangle";
    default: return "";
  }
}

struct Where {
  long polygon = -1;
  long ring = -1;
  long vertex = -1;
};

class WkbReader {
 public:
  WkbReader(std::string_view bytes, std::vector<std::string>* part_names) : bytes_(bytes), part_names_(part_names) {}

  MultiPolygon read() {
    if (bytes_.empty()) fail(0, "empty input: expected a WKB Polygon, MultiPolygon or GeometryCollection");
    read_geometry(false);
    if (pos_ != bytes_.size()) {
      fail(pos_, std::to_string(bytes_.size() - pos_) + " bytes after the end of the geometry");
    }
    return std::move(result_);
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    std::string msg = "WKB byte " + std::to_string(at);
    if (where_.polygon >= 0) {
      msg += " (polygon " + std::to_string(where_.polygon);
      if (where_.ring >= 0) msg += ", ring " + std::to_string(where_.ring);
      if (where_.vertex >= 0) msg += ", vertex " + std::to_string(where_.vertex);
      msg += ")";
    }
    throw InvalidInput(msg + ": " + what);
  }

  void need(std::size_t n, const char* what) const {
    if (bytes_.size() - pos_ < n) {
      fail(pos_, std::string("unexpected end of input; expected ") + what + " (" + std::to_string(n) +
                     " bytes, " + std::to_string(bytes_.size() - pos_) + " left)");
    }
  }

  template <class T>
  T read_raw(bool little, const char* what) {
    need(sizeof(T), what);
    std::uint8_t b[sizeof(T)];
    std::memcpy(b, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    if (little != (std::endian::native == std::endian::little)) {
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    }
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
  }

  bool read_byte_order() {
    need(1, "a byte order (0 or 1)");
    const auto order = static_cast<unsigned char>(bytes_[pos_]);
    if (order > 1) fail(pos_, "byte order " + std::to_string(order) + " is neither 0 (big endian) nor 1 (little endian)");
    ++pos_;
    return order == 1;
  }

  // A count of elements that take at least `min_bytes` each: never more than what is left.
  std::uint32_t read_count(bool little, const char* what, std::size_t min_bytes) {
    const std::size_t at = pos_;
    const auto n = read_raw<std::uint32_t>(little, what);
    if (static_cast<std::uint64_t>(n) * min_bytes > bytes_.size() - pos_) {
      fail(at, std::string(what) + " " + std::to_string(n) + " needs at least " +
                   std::to_string(static_cast<std::uint64_t>(n) * min_bytes) + " more bytes, only " +
                   std::to_string(bytes_.size() - pos_) + " left");
    }
    return n;
  }

  // Byte order and type of the geometry at pos_; returns its 2D type code. Z and M (ISO's
  // 1000s or the extended flags) set the coordinates per vertex, the same for the whole input
  // as in read_wkt: the extra ones are checked and dropped (the operation is planar).
  std::uint32_t read_header(bool& little) {
    little = read_byte_order();
    const std::size_t at = pos_;
    std::uint32_t type = read_raw<std::uint32_t>(little, "a geometry type");
    int coordinates = 2 + ((type & ewkb_z) ? 1 : 0) + ((type & ewkb_m) ? 1 : 0);
    const bool extended = (type & (ewkb_z | ewkb_m)) != 0;
    type &= ~(ewkb_z | ewkb_m);
    if (type & ewkb_srid) {
      type &= ~ewkb_srid;
      read_raw<std::uint32_t>(little, "an SRID");
    }
    const std::uint32_t base = type % 1000;
    if (type >= 1000 && type < 4000 && !type_name(base).empty()) {
      if (extended) fail(at, "geometry type " + std::to_string(type) + " has both ISO and extended Z/M flags");
      coordinates = 2 + static_cast<int>(type / 1000 == 3 ? 2 : 1);
      type = base;
    }
    if (type != base || type_name(base).empty()) fail(at, "unknown geometry type " + std::to_string(type));
    if (coordinates_ != 0 && coordinates != coordinates_) {
      fail(at, type_name(base) + " has " + std::to_string(coordinates) +
                   " coordinates per vertex, but the geometries before have " + std::to_string(coordinates_));
    }
    coordinates_ = coordinates;
    return base;
  }

  void read_geometry(bool inside_collection) {
    const std::size_t at = pos_;
    bool little = true;
    const std::uint32_t type = read_header(little);
    switch (type) {
      case wkb_polygon:
        read_polygon(little);
        return;
      case wkb_multipolygon: {
        const std::uint32_t n = read_count(little, "polygon count", 9);
        for (std::uint32_t i = 0; i < n; ++i) {
          const std::size_t part = pos_;
          bool part_little = true;
          if (read_header(part_little) != wkb_polygon) fail(part, "a MultiPolygon holds Polygons only");
          read_polygon(part_little);
        }
        return;
      }
      case wkb_collection: {
        if (inside_collection) {
          fail(at, "nested GeometryCollection is not supported; list its polygons in the outer collection");
        }
        const std::uint32_t n = read_count(little, "geometry count", 9);
        for (std::uint32_t i = 0; i < n; ++i) read_geometry(true);
        return;
      }
      case 1: case 2: case 4: case 5: case 8: case 9: case 11:
        fail(at, type_name(type) + " is not a polygonal geometry; expected Polygon, MultiPolygon or "
                                   "GeometryCollection");
      default:
        fail(at, type_name(type) + " is not supported; use Polygon or MultiPolygon");
    }
  }

  void read_polygon(bool little) {
    where_.polygon = static_cast<long>(polygon_count_++);
    const std::uint32_t rings = read_count(little, "ring count", 4);
    OgcPolygon polygon;
    for (std::uint32_t r = 0; r < rings; ++r) {
      where_.ring = static_cast<long>(r);
      const std::size_t ring_at = pos_;
      const std::uint32_t n = read_count(little, "point count", coordinate_bytes * static_cast<std::size_t>(coordinates_));
      if (n == 0) {
        // As in WKT: an empty hole adds nothing, an empty shell would orphan its holes.
        if (r == 0) fail(ring_at, "a shell ring cannot be empty; an empty polygon has no rings");
        continue;
      }
      Ring ring;
      ring.reserve(n);
      for (std::uint32_t v = 0; v < n; ++v) {
        where_.vertex = static_cast<long>(v);
        const std::size_t vertex_at = pos_;
        const double x = read_raw<double>(little, "an x coordinate");
        const double y = read_raw<double>(little, "a y coordinate");
        if (!std::isfinite(x) || !std::isfinite(y)) {
          fail(vertex_at, std::string(std::isfinite(x) ? "y" : "x") + " coordinate is not finite");
        }
        for (int c = 2; c < coordinates_; ++c) {
          const std::size_t extra_at = pos_;
          if (!std::isfinite(read_raw<double>(little, c == 2 ? "a third coordinate" : "a fourth coordinate"))) {
            fail(extra_at, std::string(c == 2 ? "third" : "fourth") + " coordinate is not finite");
          }
        }
        ring.push_back(Point{x, y});
      }
      const io_detail::OgcRingProblem problem = io_detail::check_ogc_ring(ring);
      if (problem != io_detail::OgcRingProblem::not_closed) where_.vertex = -1;
      if (problem != io_detail::OgcRingProblem::none) fail(ring_at, io_detail::describe_ogc_ring_problem(ring, problem));
      where_.vertex = -1;
      io_detail::remove_repeated_vertices(ring);
      if (polygon.shell.empty()) {
        polygon.shell = std::move(ring);
      } else {
        polygon.holes.push_back(std::move(ring));
      }
    }
    if (!polygon.shell.empty()) {
      result_.push_back(std::move(polygon));
      if (part_names_ != nullptr) part_names_->push_back("polygon " + std::to_string(where_.polygon));
    }
    where_ = {};
  }

  std::string_view bytes_;
  std::size_t pos_ = 0;
  std::size_t polygon_count_ = 0;
  int coordinates_ = 0;  // per vertex, once the first header is read: 2, 3 (Z or M) or 4 (ZM)
  Where where_;
  MultiPolygon result_;
  std::vector<std::string>* part_names_;
};

}  // namespace

MultiPolygon read_wkb(std::string_view bytes, std::vector<std::string>* part_names) {
  return WkbReader(bytes, part_names).read();
}

}  // namespace mk
