// Failure pictures: io's write_svg panels side by side, and a zoom panel drawn here with
// exact relative coordinates, because at ulp scale neither doubles nor SVG renderers
// (single precision) can place the points. [MK89 §3.3]
// Preconditions: see pictures.hpp.
#include "experiments/pictures.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "arithmetic/nearest_double.hpp"
#include "io/svg.hpp"

namespace mk::experiments {

namespace {

std::string number(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

std::string escape(const std::string& t) {
  std::string o;
  for (const char c : t) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

// An io/svg picture re-rooted as a nested <svg> at (x, y); w and h receive its size.
std::string panel(const std::string& svg, double x, double y, double& w, double& h) {
  const auto attr = [&](const std::string& name) {
    const auto p = svg.find(name + "=\"");
    return p == std::string::npos ? 600.0 : std::stod(svg.substr(p + name.size() + 2));
  };
  w = attr("width");
  h = attr("height");
  std::string s = svg;
  const auto decl = s.find("<?xml");
  if (decl != std::string::npos) s.erase(decl, s.find("?>", decl) + 2 - decl);
  const std::string root = "<svg xmlns=\"http://www.w3.org/2000/svg\"";
  const auto p = s.find(root);
  if (p != std::string::npos) s.replace(p, root.size(), "<svg x=\"" + number(x) + "\" y=\"" + number(y) + "\"");
  return s;
}

constexpr double zoom_size = 420;  // pixels of the zoom panel's square

// Liang-Barsky: clips segment pq to [-1, 1]^2; false when nothing is left.
bool clip(double& px, double& py, double& qx, double& qy) {
  double t0 = 0, t1 = 1;
  const double dx = qx - px, dy = qy - py;
  const double ps[4] = {-dx, dx, -dy, dy};
  const double qs[4] = {px + 1, 1 - px, py + 1, 1 - py};
  for (int i = 0; i < 4; ++i) {
    if (ps[i] == 0) {
      if (qs[i] < 0) return false;
      continue;
    }
    const double t = qs[i] / ps[i];
    if (ps[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  if (t0 > t1) return false;
  const double ax = px + t0 * dx, ay = py + t0 * dy, bx = px + t1 * dx, by = py + t1 * dy;
  px = ax, py = ay, qx = bx, qy = by;
  return true;
}

// The window's coordinates of a point, computed exactly, then rounded to the nearest
// double (the one rounding of rationals, arithmetic/nearest_double.hpp).
std::pair<double, double> local(const Window& w, const Point& p) {
  const mpq_class hw(w.half_width);
  const mpq_class x = (mpq_class(p.x) - mpq_class(w.centre.x)) / hw;
  const mpq_class y = (mpq_class(p.y) - mpq_class(w.centre.y)) / hw;
  return {nearest_double(x), nearest_double(y)};
}

std::string pixel(double v, bool flip) { return number((flip ? 1 - v : 1 + v) * zoom_size / 2); }

// Ring outlines clipped to the window, as SVG lines, and the vertices inside it as dots.
std::string outlines(const Window& w, const std::vector<std::vector<Point>>& rings, const std::string& colour,
                     double stroke, const std::string& dash) {
  std::string out;
  for (const auto& r : rings) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (r.size() == 1 || (r.size() == 2 && i == 1)) break;
      auto [px, py] = local(w, r[i]);
      auto [qx, qy] = local(w, r[(i + 1) % r.size()]);
      if (!clip(px, py, qx, qy)) continue;
      out += "<line x1=\"" + pixel(px, false) + "\" y1=\"" + pixel(py, true) + "\" x2=\"" + pixel(qx, false) + "\" y2=\"" +
             pixel(qy, true) + "\" stroke=\"" + colour + "\" stroke-width=\"" + number(stroke) + "\"" +
             (dash.empty() ? "" : " stroke-dasharray=\"" + dash + "\"") + "/>\n";
    }
    for (const auto& v : r) {
      const auto [x, y] = local(w, v);
      if (std::abs(x) > 1 || std::abs(y) > 1) continue;
      out += "<circle cx=\"" + pixel(x, false) + "\" cy=\"" + pixel(y, true) + "\" r=\"" + number(stroke + 1.5) +
             "\" fill=\"" + colour + "\"/>\n";
    }
  }
  return out;
}

std::vector<std::vector<Point>> rings_of(const Output& o) {
  std::vector<std::vector<Point>> out;
  for (const auto& c : o.irreducible) out.push_back(c.vertices);
  return out;
}

// The grid's points inside the window as small grey crosses, when there are few enough
// to tell apart (a snap rounding's pixel centres: its vertices lie on them).
std::string grid_points(const Window& w, double spacing) {
  if (!(spacing > 0) || !std::isfinite(spacing) || !(w.half_width / spacing <= 12)) return {};
  const double x0 = std::ceil((w.centre.x - w.half_width) / spacing), y0 = std::ceil((w.centre.y - w.half_width) / spacing);
  // Indices up to 25 past these are integers below 2^53, hence doubles.
  if (!(std::abs(x0) + 26 < 0x1p53 && std::abs(y0) + 26 < 0x1p53)) return {};
  std::string out;
  for (int i = 0; i <= 25; ++i) {
    for (int j = 0; j <= 25; ++j) {
      // Integers below 2^53 times a power of two: the grid point is exact.
      const Point g{(x0 + i) * spacing, (y0 + j) * spacing};
      if (!std::isfinite(g.x) || !std::isfinite(g.y)) continue;
      const auto [x, y] = local(w, g);
      if (std::abs(x) > 1 || std::abs(y) > 1) continue;
      const std::string cx = pixel(x, false), cy = pixel(y, true);
      out += "<path d=\"M" + cx + " " + cy + "m-3 0h6m-3 -3v6\" stroke=\"#aaa\" stroke-width=\"1\"/>\n";
    }
  }
  return out;
}

std::string zoom_panel(const Window& w, const Polygon& a, const Polygon& b, const Output& exact,
                       const std::optional<Output>& kernel, double grid) {
  std::string out = "<rect width=\"" + number(zoom_size) + "\" height=\"" + number(zoom_size) +
                    "\" fill=\"white\" stroke=\"#999\"/>\n";
  out += grid_points(w, grid);
  out += outlines(w, a.rings, "#1f77b4", 1, "");
  out += outlines(w, b.rings, "#ff7f0e", 1, "");
  out += outlines(w, rings_of(exact), "#2ca02c", 4, "");
  if (kernel) out += outlines(w, rings_of(*kernel), "#d62728", 1.5, "6 3");
  return out;
}

// Distance from p to the nearest edge or vertex of the output's rings (in doubles: only
// the size of the zoom window depends on it).
double distance_to(const Output& o, const Point& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : o.irreducible) {
    const auto& r = c.vertices;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point& a = r[i];
      const Point& b = r[(i + 1) % r.size()];
      const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
      const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y));
    }
  }
  return best;
}

}  // namespace

std::optional<Window> difference_window(const Output& exact, const Output& kernel, const ZoomOptions& options) {
  // Vertex counts, not sets: rounding can merge two exact vertices into one double.
  std::map<std::pair<double, double>, int> count;  // kernel's minus exact's
  double lo_x = std::numeric_limits<double>::infinity(), hi_x = -lo_x, lo_y = lo_x, hi_y = -lo_x;
  for (const auto& c : exact.irreducible) {
    for (const auto& v : c.vertices) {
      --count[{v.x, v.y}];
      lo_x = std::min(lo_x, v.x), hi_x = std::max(hi_x, v.x), lo_y = std::min(lo_y, v.y), hi_y = std::max(hi_y, v.y);
    }
  }
  for (const auto& c : kernel.irreducible) {
    for (const auto& v : c.vertices) ++count[{v.x, v.y}];
  }
  std::optional<Point> at;
  const Output* other = &exact;
  for (const auto& [v, n] : count) {
    if (n != 0) {
      at = Point{v.first, v.second};
      other = n > 0 ? &exact : &kernel;
      break;
    }
  }
  if (!at || (other->irreducible.empty() && !options.always)) return std::nullopt;
  // A vertex of one output where the other has none (a ring that collapsed) is its own
  // neighbourhood: the window's least width decides.
  const double nearest = other->irreducible.empty() ? 0 : distance_to(*other, *at);
  const double scale = std::max({std::abs(at->x), std::abs(at->y), std::numeric_limits<double>::min()});
  const double half = std::max({3 * nearest, 6 * (std::nextafter(scale, HUGE_VAL) - scale), options.min_half_width});
  const double extent = std::max(hi_x - lo_x, hi_y - lo_y);
  if (!options.always && std::isfinite(extent) && half > extent / 20) return std::nullopt;  // visible without zooming
  return Window{*at, half};
}

std::string failure_picture(const Polygon& a, const Polygon& b, const Output& exact, const std::string& exact_title,
                            const std::optional<Output>& kernel_output, const std::string& kernel_title,
                            const ZoomOptions& zoom_options) {
  // Polygons with non-finite coordinates (an overflowed construction) cannot be drawn.
  std::optional<Output> kernel = kernel_output;
  if (kernel) {
    std::erase_if(kernel->irreducible, [](const OutputIrreducible& c) {
      return std::any_of(c.vertices.begin(), c.vertices.end(),
                         [](const Point& v) { return !std::isfinite(v.x) || !std::isfinite(v.y); });
    });
    std::erase_if(kernel->dangling_edges, [](const std::pair<Point, Point>& e) {
      return !std::isfinite(e.first.x + e.first.y + e.second.x + e.second.y);
    });
    std::erase_if(kernel->isolated_points, [](const Point& v) { return !std::isfinite(v.x + v.y); });
    kernel->polygons.clear();
  }
  double w1 = 0, h1 = 0, w2 = 0, h2 = 0;
  const std::string left = panel(write_svg(a, b, exact), 0, 28, w1, h1);
  const std::string right = panel(write_svg(a, b, kernel.value_or(Output{})), w1 + 20, 28, w2, h2);
  const std::optional<Window> zoom =
      kernel ? difference_window(exact, *kernel, zoom_options) : std::nullopt;
  const double width = w1 + 20 + w2 + (zoom ? 20 + zoom_size : 0);
  const double height = std::max({h1, h2, zoom ? zoom_size + 40 : 0.0}) + 28;
  // Titles cut to their panel's width (about 7.5 pixels a character).
  const auto text = [](double x, const std::string& t, double room) {
    const auto chars = static_cast<std::size_t>(std::max(10.0, room / 7.5));
    const std::string cut = t.size() > chars ? t.substr(0, chars - 3) + "..." : t;
    return "<text x=\"" + number(x) + "\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">" + escape(cut) +
           "</text>\n";
  };
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" +
                    number(height) + "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out += text(8, exact_title, w1) + text(w1 + 28, kernel_title, w2);
  out += left + "\n" + right + "\n";
  if (zoom) {
    const double x = w1 + 20 + w2 + 20;
    char buf[160];
    std::snprintf(buf, sizeof buf, "zoom: %.3g wide around (%.17g, %.17g)", 2 * zoom->half_width, zoom->centre.x,
                  zoom->centre.y);
    out += text(x, buf, zoom_size + 200);
    out += "<svg x=\"" + number(x) + "\" y=\"28\" width=\"" + number(zoom_size) + "\" height=\"" + number(zoom_size) +
           "\">\n" + zoom_panel(*zoom, a, b, exact, kernel, zoom_options.grid) + "</svg>\n";
    out += "<text x=\"" + number(x) + "\" y=\"" + number(zoom_size + 50) +
           "\" font-family=\"sans-serif\" font-size=\"12\">" +
           escape("A blue, B orange, " + zoom_options.left_name + " green, " + zoom_options.right_name + " red dashed" +
                  (zoom_options.grid > 0 ? ", grid points grey" : "")) +
           "</text>\n";
  }
  return out + "</svg>\n";
}

}  // namespace mk::experiments
