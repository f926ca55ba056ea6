// Format sniffing and dispatch to the readers (see format.hpp).
// [OGC06-103 §7] [RFC7946] [MK89 §2.2]
// Preconditions: none.
#include "io/format.hpp"

#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"

#include "io/geojson.hpp"
#include "io/native_json.hpp"
#include "io/parts.hpp"
#include "io/wkt.hpp"

namespace mk {

namespace {

bool ends_with_ignoring_case(std::string_view s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  s = s.substr(s.size() - suffix.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != suffix[i]) return false;
  }
  return true;
}

bool is_json_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string_view skip_leading_space(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  while (!text.empty() && (is_json_space(text.front()) || text.front() == '\f' || text.front() == '\v')) {
    text.remove_prefix(1);
  }
  return text;
}

// True when the top-level JSON object has a "rings" key (or "polygons": the result form). A small scanner (strings, escapes,
// nesting depth) rather than a parse: it stops at the key and never builds a document.
// Malformed JSON simply yields false; the GeoJSON reader then reports the syntax error.
bool top_object_has_rings(std::string_view text) {
  text = skip_leading_space(text);
  if (text.empty() || text.front() != '{') return false;
  int depth = 0;
  bool expecting_key = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      const std::size_t start = i + 1;
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\') ++i;
      }
      if (i >= text.size()) return false;
      if (depth == 1 && expecting_key) {
        const std::string_view key = text.substr(start, i - start);
        if (key == "rings" || key == "polygons") return true;  // polygons: the output form
        expecting_key = false;
      }
    } else if (c == '{' || c == '[') {
      ++depth;
      expecting_key = depth == 1;
    } else if (c == '}' || c == ']') {
      if (--depth == 0) return false;
    } else if (c == ',') {
      expecting_key = depth == 1;
    }
  }
  return false;
}

// Whether the line starts a WKT geometry: letters, then `(` or the word EMPTY (after a
// dimension tag, if any).
bool starts_wkt_geometry(std::string_view line) {
  line = skip_leading_space(line);
  std::size_t n = 0;
  const auto is_letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  while (n < line.size() && is_letter(line[n])) ++n;
  if (n == 0) return false;
  line = skip_leading_space(line.substr(n));
  for (const std::string_view tag : {"ZM", "Z", "M", "zm", "z", "m"}) {
    if (line.starts_with(tag) && line.size() > tag.size() && !is_letter(line[tag.size()])) {
      line = skip_leading_space(line.substr(tag.size()));
      break;
    }
  }
  return line.starts_with('(') || line.starts_with("EMPTY") || line.starts_with("empty") || line.starts_with("Empty");
}

// The non-blank lines of a text with their 1-based numbers, when there are two or more and
// each starts a WKT geometry; else nothing.
std::vector<std::pair<std::size_t, std::string_view>> wkt_lines(std::string_view text) {
  std::vector<std::pair<std::size_t, std::string_view>> lines;
  std::size_t number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    ++number;
    if (!skip_leading_space(line).empty()) {
      if (!starts_wkt_geometry(line)) return {};
      lines.emplace_back(number, line);
    }
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  if (lines.size() < 2) return {};
  return lines;
}

}  // namespace

std::string_view format_name(Format format) {
  switch (format) {
    case Format::wkt: return "WKT";
    case Format::geojson: return "GeoJSON";
    case Format::native_json: return "native JSON";
  }
  return "?";
}

Format sniff_format(std::string_view text, std::string_view filename_hint) {
  if (ends_with_ignoring_case(filename_hint, ".wkt")) return Format::wkt;
  if (ends_with_ignoring_case(filename_hint, ".geojson")) return Format::geojson;
  const bool is_json = ends_with_ignoring_case(filename_hint, ".json") ||
                       skip_leading_space(text).starts_with('{');
  if (!is_json) return Format::wkt;
  return top_object_has_rings(text) ? Format::native_json : Format::geojson;
}

PolygonInput read_polygon_input(std::string_view text, std::string_view filename_hint) {
  PolygonInput in;
  in.format = sniff_format(text, filename_hint);
  PartNames names;
  switch (in.format) {
    case Format::native_json:
      {
        ExactPolygon exact = read_native_json_exact(text);
        if (auto d = as_double_polygon(exact)) {
          in.polygon = std::move(*d);
        } else {
          validate_exact_coordinates(exact, "");
          in.polygon = nearest_polygon(exact);
          in.exact = std::move(exact);
        }
      }
      for (std::size_t r = 0; r < in.polygon.rings.size(); ++r) in.ring_names.push_back("rings[" + std::to_string(r) + "]");
      return in;
    case Format::wkt:
    case Format::geojson:
      break;
  }
  names.json_paths = in.format == Format::geojson;
  const MultiPolygon mp = in.format == Format::wkt ? read_wkt(text, &names.parts) : read_geojson(text, &names.parts);
  in.polygon = to_checked_polygon(mp, names);
  for (std::size_t p = 0; p < mp.size(); ++p) {
    for (std::size_t k = 0; k <= mp[p].holes.size(); ++k) in.ring_names.push_back(ring_name(names, p, k));
  }
  return in;
}

MultiPolygon read_parts_input(std::string_view text, std::string_view filename_hint) {
  switch (sniff_format(text, filename_hint)) {
    case Format::native_json:
      throw InvalidInput("native JSON has no parts (shells and holes); give WKT or GeoJSON");
    case Format::geojson:
      return read_geojson(text);
    case Format::wkt:
      break;
  }
  const auto lines = wkt_lines(text);
  if (lines.empty()) return read_wkt(text);
  MultiPolygon parts;
  for (const auto& [number, line] : lines) {
    try {
      MultiPolygon mp = read_wkt(line);
      for (auto& p : mp) parts.push_back(std::move(p));
    } catch (const InvalidInput& e) {
      throw InvalidInput("line " + std::to_string(number) + ": " + e.what());
    }
  }
  return parts;
}

Polygon read_polygon(std::string_view text, std::string_view filename_hint) {
  return read_polygon_input(text, filename_hint).polygon;
}

}  // namespace mk
