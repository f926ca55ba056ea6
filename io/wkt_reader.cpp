// WKT reader for POLYGON, MULTIPOLYGON and flat GEOMETRYCOLLECTIONs of those.
// [OGC06-103 §7] (grammar) [OGC06-103 §6.1.11] (rings: closed, 3+ distinct points)
// Preconditions: none; every malformed text throws mk::InvalidInput with line and column.
#include <array>
#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/error.hpp"
#include "io/ring_rules.hpp"
#include "io/text_util.hpp"
#include "io/wkt.hpp"

namespace mk {

namespace {

using io_detail::excerpt;

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
// Characters that may belong to a number token. Letters are included so that "nan",
// "inf" or "1e5x" are seen whole and reported as one token.
bool is_number_char(char c) { return is_letter(c) || is_digit(c) || c == '.' || c == '+' || c == '-'; }
char to_upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

std::string upper_case(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = to_upper(c);
  return u;
}

enum class GeometryKind { polygon, multipolygon, collection, not_polygonal, unsupported, unknown };

struct KnownType {
  std::string_view name;
  GeometryKind kind;
};

constexpr std::array<KnownType, 16> known_types{{
    {"POLYGON", GeometryKind::polygon},
    {"MULTIPOLYGON", GeometryKind::multipolygon},
    {"GEOMETRYCOLLECTION", GeometryKind::collection},
    {"POINT", GeometryKind::not_polygonal},
    {"LINESTRING", GeometryKind::not_polygonal},
    {"LINEARRING", GeometryKind::not_polygonal},
    {"MULTIPOINT", GeometryKind::not_polygonal},
    {"MULTILINESTRING", GeometryKind::not_polygonal},
    {"CIRCULARSTRING", GeometryKind::not_polygonal},
    {"COMPOUNDCURVE", GeometryKind::not_polygonal},
    {"MULTICURVE", GeometryKind::not_polygonal},
    {"CURVEPOLYGON", GeometryKind::unsupported},
    {"MULTISURFACE", GeometryKind::unsupported},
    {"POLYHEDRALSURFACE", GeometryKind::unsupported},
    {"TRIANGLE", GeometryKind::unsupported},
    {"TIN", GeometryKind::unsupported},
}};

GeometryKind kind_of(std::string_view upper) {
  for (const auto& t : known_types) {
    if (t.name == upper) return t.kind;
  }
  return GeometryKind::unknown;
}

bool is_dimension_tag(std::string_view upper) { return upper == "Z" || upper == "M" || upper == "ZM"; }

// Coordinates per vertex a dimension tag announces: Z and M add one, ZM two.
int coordinates_of_tag(std::string_view upper) { return upper == "ZM" ? 4 : 3; }

// "POLYGONZ", "POLYGONM", "POLYGONZM": a known type glued to a dimension tag (some writers
// emit it). Returns the tag's length, 0 when the word is not of this form.
std::size_t dimension_suffix_length(std::string_view upper) {
  for (const std::string_view suffix : {"ZM", "Z", "M"}) {
    if (upper.size() > suffix.size() && upper.ends_with(suffix) &&
        kind_of(upper.substr(0, upper.size() - suffix.size())) != GeometryKind::unknown) {
      return suffix.size();
    }
  }
  return 0;
}

bool is_non_finite_word(std::string_view token) {
  if (!token.empty() && (token[0] == '+' || token[0] == '-')) token.remove_prefix(1);
  const std::string u = upper_case(token.substr(0, 8));
  return u == "NAN" || u == "INF" || u == "INFINITY" || u.starts_with("NAN(");
}

// Indices that locate an error in the polygon structure; -1 when not applicable.
struct Where {
  long polygon = -1;
  long ring = -1;
  long vertex = -1;
};

class WktReader {
 public:
  WktReader(std::string_view text, std::vector<std::string>* part_names) : text_(text), part_names_(part_names) {}

  MultiPolygon read() {
    if (text_.starts_with("\xEF\xBB\xBF")) pos_ = 3;  // UTF-8 byte order mark
    skip_space();
    if (at_end()) {
      fail(pos_, "empty input: expected a polygonal geometry such as "
                 "POLYGON ((0 0, 1 0, 0 1, 0 0)) or POLYGON EMPTY");
    }
    read_geometry(false);
    skip_space();
    if (!at_end()) fail(pos_, "unexpected text after the end of the geometry: " + found(pos_));
    return std::move(result_);
  }

 private:
  // --- error reporting -------------------------------------------------------------------

  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    std::string msg = "WKT " + io_detail::describe_position(text_, at);
    if (where_.polygon >= 0) {
      msg += " (polygon " + std::to_string(where_.polygon);
      if (where_.ring >= 0) msg += ", ring " + std::to_string(where_.ring);
      if (where_.vertex >= 0) msg += ", vertex " + std::to_string(where_.vertex);
      msg += ")";
    }
    throw InvalidInput(msg + ": " + what);
  }

  // The token at `at`, quoted, for "found ..." in messages.
  std::string found(std::size_t at) const {
    if (at >= text_.size()) return "end of input";
    std::size_t end = at;
    while (end < text_.size() && is_number_char(text_[end])) ++end;
    if (end == at) end = at + 1;
    return io_detail::quoted(excerpt(text_.substr(at, end - at)));
  }

  [[noreturn]] void fail_expected(std::string_view expected) const {
    if (at_end()) fail(pos_, "unexpected end of input; expected " + std::string(expected));
    fail(pos_, "expected " + std::string(expected) + ", found " + found(pos_));
  }

  // --- lexing ------------------------------------------------------------------------------

  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[pos_]; }
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
  }
  std::string_view read_word() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_letter(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  void expect(char c, std::string_view expected) {
    skip_space();
    if (peek() != c) fail_expected(expected);
    ++pos_;
  }
  // After an element of a list: true for ',' (another element follows), false for ')'.
  bool next_in_list(std::string_view expected) {
    skip_space();
    const char c = peek();
    if (c == ',' || c == ')') {
      ++pos_;
      return c == ',';
    }
    fail_expected(expected);
  }

  double read_coordinate(std::string_view which) {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_number_char(text_[pos_])) ++pos_;
    std::string_view token = text_.substr(start, pos_ - start);
    if (token.empty()) fail_expected("a number (the " + std::string(which) + " coordinate)");
    if (is_non_finite_word(token)) {
      fail(start, std::string(which) + " coordinate '" + excerpt(token) +
                      "' is not a finite number; NaN and infinity are not allowed");
    }
    // from_chars does not take a leading '+', which WKT writers sometimes emit.
    std::string_view digits = token;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') {
      digits.remove_prefix(1);
    }
    double value = 0;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (r.ec == std::errc::invalid_argument || r.ptr != digits.data() + digits.size()) {
      fail(start, "malformed number '" + excerpt(token) + "'");
    }
    if (r.ec != std::errc()) {
      fail(start, std::string(which) + " coordinate '" + excerpt(token) +
                      "' is not representable as a double (too large or too small in "
                      "magnitude)");
    }
    return value;
  }

  // --- grammar -----------------------------------------------------------------------------

  void read_geometry(bool inside_collection) {
    skip_space();
    const std::size_t start = pos_;
    const std::string_view word = read_word();
    if (word.empty()) fail_expected("a geometry type such as POLYGON or MULTIPOLYGON");
    // Geometry keywords are short; a long word is unknown and is not copied whole.
    std::string upper = upper_case(word.substr(0, 32));
    GeometryKind kind = word.size() > 32 ? GeometryKind::unknown : kind_of(upper);
    bool glued_tag = false;
    if (kind == GeometryKind::unknown && word.size() <= 32) {
      if (const std::size_t tag = dimension_suffix_length(upper); tag > 0) {
        glued_tag = true;
        set_dimension(start, coordinates_of_tag(upper.substr(upper.size() - tag)), upper);
        upper.resize(upper.size() - tag);
        kind = kind_of(upper);
      }
    }
    switch (kind) {
      case GeometryKind::not_polygonal:
        fail(start, upper + " is not a polygonal geometry; expected POLYGON, MULTIPOLYGON or "
                            "GEOMETRYCOLLECTION");
      case GeometryKind::unsupported:
        fail(start, upper + " is not supported; use POLYGON or MULTIPOLYGON");
      case GeometryKind::unknown:
        fail(start, "unknown geometry type '" + excerpt(word) + "'");
      case GeometryKind::collection:
        if (inside_collection) {
          fail(start, "nested GEOMETRYCOLLECTION is not supported; list its polygons in the "
                      "outer collection");
        }
        break;
      default: break;
    }
    if (read_empty_or_open(upper, !glued_tag)) {
      if (kind == GeometryKind::polygon) ++polygon_count_;
      return;
    }
    switch (kind) {
      case GeometryKind::polygon: read_polygon_body(); break;
      case GeometryKind::multipolygon:
        do {
          if (!read_empty_or_open("POLYGON")) {
            read_polygon_body();
          } else {
            ++polygon_count_;
          }
        } while (next_in_list("',' or ')' after a polygon of the MULTIPOLYGON"));
        break;
      case GeometryKind::collection:
        do {
          read_geometry(true);
        } while (next_in_list("',' or ')' after a geometry of the GEOMETRYCOLLECTION"));
        break;
      default: break;
    }
  }

  // After a keyword: true for EMPTY; false after consuming '('. A Z, M or ZM tag between
  // them sets how many coordinates each vertex has (the extra ones are dropped).
  bool read_empty_or_open(std::string_view keyword, bool tag_allowed = true) {
    skip_space();
    if (is_letter(peek())) {
      const std::size_t start = pos_;
      const std::string_view word = read_word();
      const std::string upper = upper_case(word.substr(0, 16));
      if (upper == "EMPTY" && word.size() == 5) return true;
      if (tag_allowed && is_dimension_tag(upper) && word.size() <= 2) {
        set_dimension(start, coordinates_of_tag(upper), std::string(keyword) + " " + upper);
        return read_empty_or_open(keyword, false);
      }
      pos_ = start;
    }
    expect('(', "'(' or EMPTY after " + std::string(keyword));
    return false;
  }

  // Every vertex of an input has the same number of coordinates: 2 (x y), 3 (x y z or
  // x y m) or 4 (x y z m), fixed by the first tag or the first vertex.
  void set_dimension(std::size_t at, int coordinates, const std::string& what) {
    if (coordinates_ != 0 && coordinates_ != coordinates) {
      fail(at, what + " has " + std::to_string(coordinates) + " coordinates per vertex, but the vertices before have " +
                   std::to_string(coordinates_));
    }
    coordinates_ = coordinates;
  }

  // A polygon's ring list; the opening '(' has been consumed.
  void read_polygon_body() {
    where_.polygon = static_cast<long>(polygon_count_++);
    OgcPolygon polygon;
    long ring_index = 0;
    do {
      where_.ring = ring_index;
      skip_space();
      if (is_letter(peek())) {
        const std::size_t start = pos_;
        if (upper_case(read_word().substr(0, 8)) == "EMPTY") {
          // An empty hole adds nothing (GEOS's suites contain them); an empty shell would
          // leave its holes without a polygon.
          if (ring_index == 0) fail(start, "a shell ring cannot be EMPTY; write POLYGON EMPTY for an empty polygon");
          ++ring_index;
          where_.ring = -1;
          continue;
        }
        pos_ = start;
      }
      const std::size_t ring_start = pos_;
      expect('(', "'(' to start a ring");
      Ring ring;
      const std::size_t last_vertex = read_ring_body(ring);
      check_ring(ring, ring_start, last_vertex);
      io_detail::remove_repeated_vertices(ring);
      if (ring_index == 0) {
        polygon.shell = std::move(ring);
      } else {
        polygon.holes.push_back(std::move(ring));
      }
      ++ring_index;
      where_.ring = -1;
    } while (next_in_list("',' or ')' after a ring"));
    result_.push_back(std::move(polygon));
    if (part_names_ != nullptr) part_names_->push_back("polygon " + std::to_string(where_.polygon));
    where_.polygon = -1;
  }

  // The vertices of a ring, in closed form; the opening '(' has been consumed. Returns the
  // text offset of the last vertex, where an unclosed ring is reported.
  std::size_t read_ring_body(Ring& ring) {
    std::size_t last_vertex = pos_;
    long vertex = 0;
    while (true) {
      where_.vertex = vertex++;
      skip_space();
      last_vertex = pos_;
      const double x = read_coordinate("x");
      const double y = read_coordinate("y");
      ring.push_back(Point{x, y});
      // Z and M, checked like x and y and then dropped: the operation is planar.
      int count = 2;
      for (skip_space(); count < 5 && is_number_char(peek()); skip_space()) {
        read_coordinate(count == 2 ? "third" : "fourth");
        ++count;
      }
      if (count > 4) fail(pos_, "vertex has more than 4 coordinates; at most x y z m");
      if (coordinates_ == 0) coordinates_ = count;
      if (count != coordinates_) {
        fail(last_vertex, "vertex has " + std::to_string(count) + " coordinates, but " +
                              (coordinates_ == 2 ? std::string("the vertices before have 2")
                                                 : "this input's vertices have " + std::to_string(coordinates_)));
      }
      if (!next_in_list("',' or ')' after a vertex")) break;
    }
    where_.vertex = -1;
    return last_vertex;
  }

  void check_ring(const Ring& ring, std::size_t ring_start, std::size_t last_vertex) {
    const io_detail::OgcRingProblem problem = io_detail::check_ogc_ring(ring);
    if (problem == io_detail::OgcRingProblem::none) return;
    std::size_t at = ring_start;
    if (problem == io_detail::OgcRingProblem::not_closed) {
      at = last_vertex;
      where_.vertex = static_cast<long>(ring.size()) - 1;
    }
    fail(at, io_detail::describe_ogc_ring_problem(ring, problem));
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t polygon_count_ = 0;
  int coordinates_ = 0;  // per vertex, once known: 2, 3 (Z or M) or 4 (ZM)
  Where where_;
  MultiPolygon result_;
  std::vector<std::string>* part_names_;
};

}  // namespace

MultiPolygon read_wkt(std::string_view text, std::vector<std::string>* part_names) {
  return WktReader(text, part_names).read();
}

}  // namespace mk
