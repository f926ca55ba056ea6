// The regression case format of artefacts.hpp: A and B as WKT when they are island-type
// polygons whose rings come shell first, each followed by the holes directly inside it,
// else as native JSON; then the operation and the regularity, and the fill rule if any; a
// set case as its parts and union_all or intersection_all. [MK89 §2.2] (rings nest:
// shells and holes for WKT) [MK89 §3.3] (each failure of an exact kernel becomes a test)
// Preconditions: see artefacts.hpp.
#include <gmpxx.h>

#include <algorithm>
#include <charconv>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "experiments/artefacts.hpp"
#include "experiments/generators.hpp"
#include "experiments/operations.hpp"
#include "io/native_json.hpp"
#include "io/wkt.hpp"

namespace mk::experiments {

namespace {

std::string number(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// Whether ring r lies inside ring s (decided at a vertex of r not on s; rings of a valid
// polygon do not cross). Empty when every vertex of r lies on s.
std::optional<bool> is_ring_inside(const Ring& r, const Ring& s) {
  for (const Point& p : r) {
    const mpq_class px(p.x), py(p.y);
    bool on = false, in = false;
    for (std::size_t i = 0; i < s.size() && !on; ++i) {
      const Point& a = s[i];
      const Point& b = s[(i + 1) % s.size()];
      const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y);
      const mpq_class cross = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
      if (cross == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
          p.y <= std::max(a.y, b.y)) {
        on = true;
      } else if ((ay > py) != (by > py) && ((by > ay) ? cross > 0 : cross < 0)) {
        in = !in;
      }
    }
    if (!on) return in;
  }
  return std::nullopt;
}

// WKT when the polygon is island-type, every ring has 3+ points, and its rings come as
// shells each followed by the holes directly inside it; empty otherwise.
std::string as_wkt(const Polygon& p) {
  if (p.type != PolygonType::island || p.rings.empty()) return {};
  const std::size_t n = p.rings.size();
  std::vector<int> depth(n, 0);
  std::vector<int> parent(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    if (p.rings[i].size() < 3) return {};
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      const auto in = is_ring_inside(p.rings[i], p.rings[j]);
      if (!in) return {};
      if (*in) ++depth[i];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (depth[i] % 2 == 0) continue;
    for (std::size_t j = 0; j < n; ++j) {
      if (j != i && depth[j] == depth[i] - 1 && is_ring_inside(p.rings[i], p.rings[j]).value_or(false)) {
        parent[i] = static_cast<int>(j);
      }
    }
  }
  std::string parts;
  std::size_t shells = 0;
  for (std::size_t i = 0; i < n;) {
    if (depth[i] % 2 != 0) return {};  // a hole not right after its shell
    std::string part = "(";
    std::size_t j = i;
    do {
      part += j == i ? "(" : ", (";
      for (const Point& q : p.rings[j]) part += number(q.x) + " " + number(q.y) + ", ";
      part += number(p.rings[j][0].x) + " " + number(p.rings[j][0].y) + ")";
      ++j;
    } while (j < n && depth[j] % 2 != 0 && parent[j] == static_cast<int>(i));
    parts += (shells++ > 0 ? ", " : "") + part + ")";
    i = j;
  }
  return shells == 1 ? "POLYGON " + parts : "MULTIPOLYGON (" + parts + ")";
}

std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n') c = ' ';
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// Every ring as given (direction and start kept, unlike write_wkt, which orients them):
// rounded kernels may fail on one ring order and not another.
std::string parts_wkt(const MultiPolygon& parts) {
  const auto ring = [](const Ring& r) {
    std::string t = "(";
    for (const Point& q : r) t += number(q.x) + " " + number(q.y) + ", ";
    return t + number(r[0].x) + " " + number(r[0].y) + ")";
  };
  std::string out = "MULTIPOLYGON (";
  for (std::size_t i = 0; i < parts.size(); ++i) {
    out += (i > 0 ? ", (" : "(") + ring(parts[i].shell);
    for (const Ring& h : parts[i].holes) out += ", " + ring(h);
    out += ")";
  }
  return out + ")";
}

std::optional<FillRule> parse_fill_rule(const std::string& name) {
  for (const FillRule r : {FillRule::evenodd, FillRule::nonzero, FillRule::positive, FillRule::negative, FillRule::union_}) {
    if (fill_rule_name(r) == name) return r;
  }
  return std::nullopt;
}

Polygon read_polygon_line(const std::string& line) {
  if (!line.empty() && line[0] == '{') return read_native_json(line);
  return to_polygon(read_wkt(line));
}

}  // namespace

std::string regression_case_text(const Polygon& a, const Polygon& b, Operation op, bool regular,
                                 const std::vector<std::string>& comments, std::optional<FillRule> fill_rule) {
  std::string out;
  for (const Polygon* p : {&a, &b}) {
    std::string line = fill_rule ? std::string() : as_wkt(*p);
    if (line.empty()) line = one_line(write_native_json(*p));
    out += line + "\n";
  }
  out += std::string(operation_name(op)) + "\n" + (regular ? "regular" : "nonregular") + "\n";
  if (fill_rule) out += "fill_rule " + std::string(fill_rule_name(*fill_rule)) + "\n";
  for (const auto& c : comments) out += "# " + c + "\n";
  return out;
}

std::string regression_case_text(const Case& c, Operation op, bool regular, const std::vector<std::string>& comments) {
  const std::optional<FillRule> rule = fill_rule_of(c.spec);
  if (!c.parts) return regression_case_text(c.a, c.b, op, regular, comments, rule);
  std::string out = parts_wkt(*c.parts) + "\nMULTIPOLYGON EMPTY\n" + run_operation_name(c.spec, op) + "\n" +
                    (regular ? "regular" : "nonregular") + "\n";
  if (rule) out += "fill_rule " + std::string(fill_rule_name(*rule)) + "\n";
  for (const auto& line : comments) out += "# " + line + "\n";
  return out;
}

RegressionCase read_regression_case(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  }
  if (lines.size() < 4) throw InvalidInput("regression case: expected 4 lines (A, B, operation, regular)");
  RegressionCase c;
  const bool set = lines[2] == "union_all" || lines[2] == "intersection_all";
  if (set) {
    c.parts = read_wkt(lines[0]);
    c.op = lines[2] == "union_all" ? Operation::union_ : Operation::intersection;
  } else {
    c.a = read_polygon_line(lines[0]);
    c.b = read_polygon_line(lines[1]);
    try {
      c.op = parse_operation(lines[2]);
    } catch (const std::invalid_argument& e) {
      throw InvalidInput(std::string("regression case line 3: ") + e.what() + " (or union_all, intersection_all)");
    }
  }
  if (lines[3] != "regular" && lines[3] != "nonregular") {
    throw InvalidInput("regression case line 4: expected 'regular' or 'nonregular'");
  }
  c.regular = lines[3] == "regular";
  if (lines.size() > 4) {
    const std::string prefix = "fill_rule ";
    if (lines[4].rfind(prefix, 0) != 0 || !(c.fill_rule = parse_fill_rule(lines[4].substr(prefix.size())))) {
      throw InvalidInput("regression case line 5: expected 'fill_rule evenodd|nonzero|positive|negative|union'");
    }
  }
  if (set) c.a = fill_rule_polygon(*c.parts, c.fill_rule.value_or(FillRule::union_));
  return c;
}

BooleanOutput replay_regression_case(const RegressionCase& c, BooleanOptions options) {
  options.op = c.op;
  options.fill_rule = c.fill_rule;
  if (!c.parts) return compute(c.a, c.b, options);
  return c.op == Operation::union_ ? union_all(*c.parts, options) : intersection_all(*c.parts, options);
}

}  // namespace mk::experiments
