// Reader and writers of the native JSON format (see native_json.hpp).
// [MK89 §2.2] [MK89 §3.1 step 6]
// Preconditions: none for the reader; the writers need finite coordinates.
#include "io/native_json.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <stdexcept>
#include <string>
#include <string_view>

#include "arithmetic/exact_text.hpp"
#include "core/error.hpp"
#include "io/json_util.hpp"
#include "io/ring_rules.hpp"
#include "io/text_util.hpp"

namespace mk {

namespace {

using io_detail::index_path;
using io_detail::Json;
using io_detail::json_type_name;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InvalidInput("native JSON at " + (path.empty() ? std::string("top level") : path) + ": " +
                     what);
}

bool is_digits(std::string_view s) {
  if (s.empty()) return false;
  for (const char c : s) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}

// "p/q" or "p" with decimal integers (optional sign on p): the exact form the writers emit
// for exact kernels. The value must be a double, because the kernels take doubles; the
// check is exact: convert to the double GMP gives, convert back, compare.
double rational_string_to_double(const std::string& text, const std::string& path) {
  std::string_view s = text;
  std::string_view body = s;
  if (!body.empty() && (body[0] == '-' || body[0] == '+')) body.remove_prefix(1);
  const std::size_t slash = body.find('/');
  const std::string_view numerator = body.substr(0, slash);
  const std::string_view denominator =
      slash == std::string_view::npos ? std::string_view("1") : body.substr(slash + 1);
  if (!is_digits(numerator) || !is_digits(denominator)) {
    fail(path, "coordinate \"" + io_detail::excerpt(text) +
                   "\" is not a number: expected a JSON number, an integer \"p\" or a "
                   "rational \"p/q\"");
  }
  if (denominator.find_first_not_of('0') == std::string_view::npos) {
    fail(path, "coordinate \"" + io_detail::excerpt(text) + "\" has a zero denominator");
  }
  mpq_class value;
  // GMP does not take a '+' sign.
  const std::string gmp_text = (s[0] == '-' ? "-" : "") + std::string(body);
  value.set_str(gmp_text, 10);
  value.canonicalize();
  const double d = value.get_d();  // truncates; exact when the value is a double
  if (!std::isfinite(d) || mpq_class(d) != value) {
    fail(path, "coordinate \"" + io_detail::excerpt(text) +
                   "\" is not exactly a double; only doubles are supported as input "
                   "coordinates");
  }
  return d;
}

double read_coordinate(const Json& j, const std::string& path) {
  if (j.is_string()) return rational_string_to_double(j.get_ref<const std::string&>(), path);
  double d = 0;
  std::string problem;
  if (!io_detail::json_number_to_double(j, d, problem)) {
    if (!j.is_number()) problem += " or a rational string \"p/q\"";
    fail(path, problem);
  }
  return d;
}

// A coordinate taken exactly: a JSON number is the double it denotes (as parsed), a string
// the exact rational or decimal it writes.
mpq_class read_exact_coordinate(const Json& j, const std::string& path) {
  if (j.is_string()) {
    const std::string& text = j.get_ref<const std::string&>();
    if (const auto v = parse_exact_number(text)) return *v;
    fail(path, "coordinate \"" + io_detail::excerpt(text) +
                   "\" is not a number: expected a JSON number, an integer \"p\", a rational \"p/q\" or a "
                   "decimal \"d.ddd\" (nonzero denominator)");
  }
  return mpq_class(read_coordinate(j, path));
}

template <class P>
P read_point(const Json& point, const std::string& point_path) {
  if constexpr (std::is_same_v<P, Point>) {
    return Point{read_coordinate(point[0], index_path(point_path, 0)), read_coordinate(point[1], index_path(point_path, 1))};
  } else {
    return P{read_exact_coordinate(point[0], index_path(point_path, 0)),
             read_exact_coordinate(point[1], index_path(point_path, 1))};
  }
}

template <class P>
BasicRing<P> read_ring(const Json& points, const std::string& path) {
  if (!points.is_array()) fail(path, "expected an array of points, found " + json_type_name(points));
  if (points.empty()) {
    fail(path, "ring is empty; a ring needs at least 1 point (1 is a one-sided polygon, 2 a "
               "two-sided one)");
  }
  BasicRing<P> ring;
  ring.reserve(points.size());
  for (std::size_t v = 0; v < points.size(); ++v) {
    const Json& point = points[v];
    const std::string point_path = index_path(path, v);
    if (!point.is_array()) fail(point_path, "expected a point [x, y], found " + json_type_name(point));
    if (point.size() != 2) {
      fail(point_path, "point has " + std::to_string(point.size()) +
                           " coordinates; expected exactly 2, [x, y]");
    }
    ring.push_back(read_point<P>(point, point_path));
  }
  if constexpr (std::is_same_v<P, Point>) {
    io_detail::remove_repeated_vertices(ring);
  } else {
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
  }
  return ring;
}

const char* type_name(PolygonType type) { return type == PolygonType::island ? "island" : "hole"; }

void append_point(std::string& out, const Point& p) {
  out.push_back('[');
  io_detail::append_double(out, p.x);
  out.push_back(',');
  io_detail::append_double(out, p.y);
  out.push_back(']');
}

void append_points(std::string& out, const std::vector<Point>& points) {
  out.push_back('[');
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) out.push_back(',');
    append_point(out, points[i]);
  }
  out.push_back(']');
}

}  // namespace

namespace {

// The output form {"kernel", "unbounded", ..., "polygons": [{"type", "vertices", "exact"}]}
// as an operand: every cycle as a ring (exact coordinates when given), type hole when
// unbounded. The paper's model reads that as the result's point set: the cycles of 3 or
// more vertices nest by parity into the area part, and cycles of 2 vertices (dangling
// edges) and of 1 (isolated points) add their points [MK89 §2.2] [BRIEF §1].
template <class P>
BasicPolygon<P> read_result_form(const Json& root) {
  BasicPolygon<P> polygon;
  if (const auto u = root.find("unbounded"); u != root.end()) {
    if (!u->is_boolean()) fail("unbounded", "expected true or false, found " + json_type_name(*u));
    polygon.type = u->template get<bool>() ? PolygonType::hole : PolygonType::island;
  }
  const Json& polygons = root.at("polygons");
  if (!polygons.is_array()) fail("polygons", "expected an array of polygons, found " + json_type_name(polygons));
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const std::string path = index_path("polygons", i);
    const Json& c = polygons[i];
    if (!c.is_object()) fail(path, "expected an object {\"type\", \"vertices\", \"exact\"}, found " + json_type_name(c));
    const auto exact = c.find("exact");
    const auto vertices = c.find("vertices");
    if (vertices == c.end()) fail(path, "missing \"vertices\" member");
    const bool use_exact = exact != c.end() && !std::is_same_v<P, Point>;
    BasicRing<P> ring = read_ring<P>(use_exact ? *exact : *vertices, path + (use_exact ? ".exact" : ".vertices"));
    if (ring.size() < 3 && polygon.type == PolygonType::hole) {
      fail(path, "an unbounded result with dangling edges or isolated points is not read back as an operand (a "
                 "hole-type polygon is the closure of its area's complement, to which degenerate rings add nothing)");
    }
    if (!ring.empty()) polygon.rings.push_back(std::move(ring));
  }
  return polygon;
}

template <class P>
BasicPolygon<P> read_polygon_form(std::string_view text) {
  const Json root = io_detail::parse_json(text, "native JSON");
  if (!root.is_object()) fail("", "expected an object {\"type\": ..., \"rings\": [...]}, found " +
                                      json_type_name(root));
  if (root.contains("polygons") && !root.contains("rings")) return read_result_form<P>(root);
  BasicPolygon<P> polygon;
  bool has_rings = false;
  for (const auto& [key, value] : root.items()) {
    if (key == "type") {
      if (value == "island") {
        polygon.type = PolygonType::island;
      } else if (value == "hole") {
        polygon.type = PolygonType::hole;
      } else {
        fail("type", "expected \"island\" or \"hole\", found " +
                         (value.is_string() ? "\"" + io_detail::excerpt(value.template get<std::string>()) + "\""
                                            : json_type_name(value)));
      }
    } else if (key == "rings") {
      has_rings = true;
      if (!value.is_array()) fail("rings", "expected an array of rings, found " + json_type_name(value));
      polygon.rings.reserve(value.size());
      for (std::size_t r = 0; r < value.size(); ++r) {
        polygon.rings.push_back(read_ring<P>(value[r], index_path("rings", r)));
      }
    } else {
      fail("", "unknown member \"" + io_detail::excerpt(key) + "\"; expected \"type\" and \"rings\"");
    }
  }
  if (!has_rings) fail("", "missing \"rings\" member");
  return polygon;
}

}  // namespace

Polygon read_native_json(std::string_view text) { return read_polygon_form<Point>(text); }

ExactPolygon read_native_json_exact(std::string_view text) { return read_polygon_form<RationalPoint>(text); }

std::string write_native_json(const Polygon& polygon) {
  std::string out = "{\"type\": \"";
  out += type_name(polygon.type);
  out += "\", \"rings\": [";
  for (std::size_t r = 0; r < polygon.rings.size(); ++r) {
    out += r > 0 ? ",\n  " : "\n  ";
    append_points(out, polygon.rings[r]);
  }
  out += polygon.rings.empty() ? "]}\n" : "\n]}\n";
  return out;
}

std::string write_native_json(const Output& output, std::string_view kernel) {
  std::string out = "{\n  \"kernel\": ";
  io_detail::append_json_string(out, kernel);
  out += ",\n  \"unbounded\": ";
  out += output.unbounded ? "true" : "false";
  out += ",\n  \"rounded_valid\": ";
  out += !output.rounded_valid ? "null" : (*output.rounded_valid ? "true" : "false");
  out += ",\n  \"polygons\": [";
  for (std::size_t i = 0; i < output.irreducible.size(); ++i) {
    const OutputIrreducible& p = output.irreducible[i];
    out += i > 0 ? ",\n    " : "\n    ";
    out += "{\"type\": \"";
    out += type_name(p.type);
    out += "\", \"vertices\": ";
    append_points(out, p.vertices);
    if (!p.exact.empty()) {
      if (p.exact.size() != 2 * p.vertices.size()) {
        throw std::logic_error("mk::Output: polygon " + std::to_string(i) + " has " +
                               std::to_string(p.exact.size()) + " exact strings for " +
                               std::to_string(p.vertices.size()) + " vertices");
      }
      out += ", \"exact\": [";
      for (std::size_t v = 0; v < p.vertices.size(); ++v) {
        if (v > 0) out.push_back(',');
        out.push_back('[');
        io_detail::append_json_string(out, p.exact[2 * v]);
        out.push_back(',');
        io_detail::append_json_string(out, p.exact[2 * v + 1]);
        out.push_back(']');
      }
      out.push_back(']');
    }
    out.push_back('}');
  }
  out += output.irreducible.empty() ? "],\n" : "\n  ],\n";
  out += "  \"dangling_edges\": [";
  for (std::size_t i = 0; i < output.dangling_edges.size(); ++i) {
    if (i > 0) out.push_back(',');
    out.push_back('[');
    append_point(out, output.dangling_edges[i].first);
    out.push_back(',');
    append_point(out, output.dangling_edges[i].second);
    out.push_back(']');
  }
  out += "],\n  \"isolated_points\": ";
  append_points(out, output.isolated_points);
  out += "\n}\n";
  return out;
}

}  // namespace mk
