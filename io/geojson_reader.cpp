// GeoJSON reader for polygonal geometries, features and feature collections.
// [RFC7946 §3.1.6] (polygons: closed linear rings of 4+ positions) [RFC7946 §3.3]
// Preconditions: none; malformed input throws mk::InvalidInput naming the element's path.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "io/geojson.hpp"
#include "io/json_util.hpp"
#include "io/ring_rules.hpp"

namespace mk {

namespace {

using io_detail::index_path;
using io_detail::Json;
using io_detail::json_type_name;
using io_detail::key_path;

// Where a GeoJSON object may appear decides which types it may have.
enum class Place { top, feature_member, feature_geometry, collection_member };

class GeoJsonReader {
 public:
  GeoJsonReader(std::vector<std::string>* part_names, std::vector<io_detail::RepeatedMember> repeated)
      : part_names_(part_names), repeated_(std::move(repeated)) {}

  MultiPolygon read(const Json& root) {
    read_object(root, "", Place::top);
    return std::move(result_);
  }

 private:
  [[noreturn]] static void fail(const std::string& path, const std::string& what) {
    throw InvalidInput("GeoJSON at " + (path.empty() ? std::string("top level") : path) + ": " +
                       what);
  }

  // A member the reader reads; repeated ones are refused (io_detail::CheckedDom), others
  // (properties, foreign members) are left alone like their values.
  const Json& member(const Json& object, std::string_view key, const std::string& path) const {
    if (!repeated_.empty()) {
      const std::string where = key_path(path, key);
      for (const auto& r : repeated_) {
        if (r.path == where) fail(where, io_detail::repeated_member_problem(r.name));
      }
    }
    const auto it = object.find(key);
    if (it == object.end()) fail(path, "missing \"" + std::string(key) + "\" member");
    return *it;
  }

  const Json& array_member(const Json& object, std::string_view key, const std::string& path) const {
    const Json& value = member(object, key, path);
    if (!value.is_array()) {
      fail(key_path(path, key), "expected an array, found " + json_type_name(value));
    }
    return value;
  }

  void read_object(const Json& j, const std::string& path, Place place) {
    if (!j.is_object()) fail(path, "expected a GeoJSON object, found " + json_type_name(j));
    const Json& type_value = member(j, "type", path);
    if (!type_value.is_string()) {
      fail(key_path(path, "type"), "expected a string, found " + json_type_name(type_value));
    }
    const std::string& type = type_value.get_ref<const std::string&>();

    if (type == "FeatureCollection") {
      if (place != Place::top) fail(path, "a FeatureCollection may only be the top-level object");
      const Json& features = array_member(j, "features", path);
      const std::string features_path = key_path(path, "features");
      for (std::size_t i = 0; i < features.size(); ++i) {
        read_object(features[i], index_path(features_path, i), Place::feature_member);
      }
    } else if (type == "Feature") {
      if (place != Place::top && place != Place::feature_member) {
        fail(path, "a Feature may only be the top-level object or a member of \"features\"");
      }
      const Json& geometry = member(j, "geometry", path);
      if (!geometry.is_null()) read_object(geometry, key_path(path, "geometry"), Place::feature_geometry);
    } else if (place == Place::feature_member) {
      fail(key_path(path, "type"), "expected \"Feature\", found \"" + io_detail::excerpt(type) + "\"");
    } else if (type == "Polygon") {
      read_polygon(array_member(j, "coordinates", path), key_path(path, "coordinates"));
    } else if (type == "MultiPolygon") {
      const Json& polygons = array_member(j, "coordinates", path);
      const std::string coordinates_path = key_path(path, "coordinates");
      for (std::size_t i = 0; i < polygons.size(); ++i) {
        const std::string polygon_path = index_path(coordinates_path, i);
        if (!polygons[i].is_array()) {
          fail(polygon_path, "expected an array of rings, found " + json_type_name(polygons[i]));
        }
        read_polygon(polygons[i], polygon_path);
      }
    } else if (type == "GeometryCollection") {
      if (place == Place::collection_member) {
        fail(path, "nested GeometryCollection is not supported; list its polygons in the outer "
                   "collection");
      }
      const Json& geometries = array_member(j, "geometries", path);
      const std::string geometries_path = key_path(path, "geometries");
      for (std::size_t i = 0; i < geometries.size(); ++i) {
        read_object(geometries[i], index_path(geometries_path, i), Place::collection_member);
      }
    } else if (type == "Point" || type == "MultiPoint" || type == "LineString" ||
               type == "MultiLineString") {
      fail(path, type + " is not a polygonal geometry; expected Polygon, MultiPolygon, "
                        "GeometryCollection, Feature or FeatureCollection");
    } else if (type == "island" || type == "hole") {
      fail(path, "unknown GeoJSON type \"" + type +
                     "\" (island and hole polygons are the native JSON format, which has a "
                     "\"rings\" member)");
    } else {
      fail(key_path(path, "type"), "unknown GeoJSON type \"" + io_detail::excerpt(type) + "\"");
    }
  }

  // An array of closed rings; the empty array is the empty polygon.
  void read_polygon(const Json& rings, const std::string& path) {
    if (rings.empty()) return;
    OgcPolygon polygon;
    for (std::size_t r = 0; r < rings.size(); ++r) {
      const std::string ring_path = index_path(path, r);
      Ring ring = read_ring(rings[r], ring_path);
      const io_detail::OgcRingProblem problem = io_detail::check_ogc_ring(ring);
      if (problem == io_detail::OgcRingProblem::not_closed) {
        fail(index_path(ring_path, ring.size() - 1),
             io_detail::describe_ogc_ring_problem(ring, problem));
      }
      if (problem != io_detail::OgcRingProblem::none) {
        fail(ring_path, io_detail::describe_ogc_ring_problem(ring, problem));
      }
      io_detail::remove_repeated_vertices(ring);
      if (r == 0) {
        polygon.shell = std::move(ring);
      } else {
        polygon.holes.push_back(std::move(ring));
      }
    }
    result_.push_back(std::move(polygon));
    if (part_names_ != nullptr) part_names_->push_back(path);
  }

  static Ring read_ring(const Json& positions, const std::string& path) {
    if (!positions.is_array()) {
      fail(path, "expected an array of positions, found " + json_type_name(positions));
    }
    Ring ring;
    ring.reserve(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
      const Json& position = positions[v];
      if (!position.is_array()) {
        fail(index_path(path, v), "expected a position [x, y], found " + json_type_name(position));
      }
      if (position.size() < 2) {
        fail(index_path(path, v), "position has " + std::to_string(position.size()) +
                                      " coordinates; expected [x, y] or [x, y, altitude]");
      }
      // [RFC7946 §3.1.1] An altitude (and any further element) is allowed: it is checked like
      // x and y, then dropped, since the operation is planar.
      Point p;
      std::string problem;
      for (std::size_t k = 0; k < position.size(); ++k) {
        double value = 0;
        if (!io_detail::json_number_to_double(position[k], value, problem)) {
          fail(index_path(index_path(path, v), k), problem);
        }
        if (k == 0) p.x = value;
        if (k == 1) p.y = value;
      }
      ring.push_back(p);
    }
    return ring;
  }

  MultiPolygon result_;
  std::vector<std::string>* part_names_;
  std::vector<io_detail::RepeatedMember> repeated_;
};

}  // namespace

MultiPolygon read_geojson(std::string_view text, std::vector<std::string>* part_names) {
  std::vector<io_detail::RepeatedMember> repeated;
  const Json root = io_detail::parse_json(text, "GeoJSON", &repeated);
  return GeoJsonReader(part_names, std::move(repeated)).read(root);
}

}  // namespace mk
