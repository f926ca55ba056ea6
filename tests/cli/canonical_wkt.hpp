// Results of the command compared by their canonical form, not as the writer's text.
// [OGC06-103 §6.1.11] (polygon rings)
// Preconditions: text from the command's WKT output.
#pragma once

#include <algorithm>
#include <charconv>
#include <string>
#include <utility>
#include <vector>

#include "core/canonical.hpp"
#include "io/wkt.hpp"

namespace mk::test {

// The canonical form of polygonal WKT output, for comparing results: where a ring starts
// and the order of holes and polygons are the writer's choice, so each ring is taken from
// its least rotation (its direction kept), holes and polygons sorted. Text that is not
// polygonal WKT (a GEOMETRYCOLLECTION with lines, an error) is returned as it is.
inline std::string canonical_wkt(const std::string& text) {
  MultiPolygon mp;
  try {
    mp = read_wkt(text);
  } catch (const std::exception&) {
    return text;
  }
  using Xy = std::pair<double, double>;
  const auto ring = [](const Ring& r) {
    std::vector<Xy> v;
    for (const Point& p : r) v.push_back({p.x, p.y});
    return least_rotation(v);
  };
  std::vector<std::vector<std::vector<Xy>>> polygons;
  for (const OgcPolygon& p : mp) {
    std::vector<std::vector<Xy>> holes;
    for (const Ring& h : p.holes) holes.push_back(ring(h));
    std::sort(holes.begin(), holes.end());
    holes.insert(holes.begin(), ring(p.shell));
    polygons.push_back(std::move(holes));
  }
  std::sort(polygons.begin(), polygons.end());
  std::string out;
  for (const auto& p : polygons) {
    out += "(";
    for (const auto& r : p) {
      out += "(";
      for (const auto& [x, y] : r) {
        char buf[64];
        char* end = std::to_chars(buf, buf + sizeof buf, x).ptr;
        *end++ = ' ';
        end = std::to_chars(end, buf + sizeof buf, y).ptr;
        out.append(buf, end).append(",");
      }
      out += ")";
    }
    out += ")";
  }
  return out.empty() ? "EMPTY" : out;
}

}  // namespace mk::test
