// SVG picture of a Boolean operation (see svg.hpp). [MK89 §2.2]
// Preconditions: finite coordinates.
#include "io/svg.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

namespace mk {

namespace {

constexpr double drawing_size = 720;  // pixels for the longer side of the bounding box
constexpr double margin = 30;
constexpr double legend_height = 34;
constexpr double min_width = 600;  // room for the legend

struct Style {
  const char* fill;
  const char* stroke;
  double fill_opacity;
};
constexpr Style style_a{"#1f77b4", "#1f77b4", 0.18};
constexpr Style style_b{"#ff7f0e", "#d35f00", 0.18};
constexpr Style style_result{"#2ca02c", "#176117", 0.55};
constexpr const char* colour_dangling = "#d62728";
constexpr const char* colour_isolated = "#7b3fb0";

// Pixel values with two decimals; anything that would print as "-0.00" prints as "0.00".
void append_number(std::string& out, double v) {
  char buf[48];
  if (std::abs(v) < 0.005) v = 0;
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 2);
  out.append(buf, r.ptr);
}

// The bounding box of every coordinate drawn, and the map from coordinates to pixels.
class Canvas {
 public:
  void include(const Point& p) {
    if (empty_) {
      lo_ = hi_ = p;
      empty_ = false;
      return;
    }
    lo_.x = std::min(lo_.x, p.x);
    lo_.y = std::min(lo_.y, p.y);
    hi_.x = std::max(hi_.x, p.x);
    hi_.y = std::max(hi_.y, p.y);
  }

  // Fixes the scale. Every coordinate is first multiplied by a power of two that brings the
  // largest magnitude near 1: exact (no rounding) for coordinates near the largest double and
  // for subnormal ones alike, so that the box's extent neither overflows (1.8e308 - -1.8e308)
  // nor vanishes (the half of 5e-324 is 0). Only coordinates far below the largest, which are
  // then far below one pixel too, can lose bits to underflow.
  void fit() {
    if (empty_) lo_ = hi_ = Point{0, 0};
    const double largest = std::max({std::abs(lo_.x), std::abs(lo_.y), std::abs(hi_.x), std::abs(hi_.y)});
    shift_ = largest > 0 ? -std::ilogb(largest) : 0;
    lo_ = scaled(lo_);
    hi_ = scaled(hi_);
    const double extent_w = hi_.x - lo_.x;  // at most 4 after scaling
    const double extent_h = hi_.y - lo_.y;
    extent_ = std::max(extent_w, extent_h);
    const double w = extent_ > 0 ? extent_w / extent_ * drawing_size : 0;
    const double h = extent_ > 0 ? extent_h / extent_ * drawing_size : 0;
    width_ = std::max(w + 2 * margin, min_width);
    drawing_height_ = std::max(h, drawing_size / 12);  // a flat box still gets a strip
    height_ = drawing_height_ + 2 * margin + legend_height;
    offset_x_ = (width_ - w) / 2;
    offset_y_ = margin + (drawing_height_ - h) / 2;
  }

  double x(double v) const {
    return offset_x_ + (extent_ > 0 ? (std::ldexp(v, shift_) - lo_.x) / extent_ * drawing_size : 0);
  }
  double y(double v) const {
    return offset_y_ + (extent_ > 0 ? (hi_.y - std::ldexp(v, shift_)) / extent_ * drawing_size : 0);
  }
  double width() const { return width_; }
  double height() const { return height_; }
  double legend_top() const { return drawing_height_ + 2 * margin; }

  void append_xy(std::string& out, const Point& p) const {
    append_number(out, x(p.x));
    out.push_back(' ');
    append_number(out, y(p.y));
  }

 private:
  Point scaled(const Point& p) const { return {std::ldexp(p.x, shift_), std::ldexp(p.y, shift_)}; }

  bool empty_ = true;
  Point lo_, hi_;  // scaled by 2^shift_ once fitted
  int shift_ = 0;
  double extent_ = 0;
  double width_ = 0, height_ = 0, drawing_height_ = 0, offset_x_ = 0, offset_y_ = 0;
};

// Path data for closed rings; rings of one point are left to the dot pass.
void append_ring_path(std::string& out, const Canvas& canvas, const Ring& ring) {
  if (ring.size() < 2) return;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    out += i == 0 ? "M" : " L";
    canvas.append_xy(out, ring[i]);
  }
  out += " Z ";
}

// The whole canvas as a subpath: with evenodd it turns the rings' inside out, which is how
// a hole-type polygon or an unbounded result is shaded.
void append_canvas_path(std::string& out, const Canvas& canvas) {
  out += "M0 0 H";
  append_number(out, canvas.width());
  out += " V";
  append_number(out, canvas.legend_top());
  out += " H0 Z ";
}

void append_region(std::string& out, const Canvas& canvas, const std::vector<const Ring*>& rings,
                   bool unbounded, const Style& style, double stroke_width) {
  std::string fill_path;
  if (unbounded) append_canvas_path(fill_path, canvas);
  std::string outline;
  for (const Ring* ring : rings) append_ring_path(outline, canvas, *ring);
  fill_path += outline;
  if (!fill_path.empty()) {
    out += "  <path fill=\"";
    out += style.fill;
    out += "\" fill-opacity=\"";
    append_number(out, style.fill_opacity);
    out += "\" fill-rule=\"evenodd\" stroke=\"none\" d=\"" + fill_path + "\"/>\n";
  }
  if (!outline.empty()) {
    out += "  <path fill=\"none\" stroke=\"";
    out += style.stroke;
    out += "\" stroke-width=\"";
    append_number(out, stroke_width);
    out += "\" stroke-linejoin=\"round\" d=\"" + outline + "\"/>\n";
  }
  for (const Ring* ring : rings) {
    if (ring->size() != 1) continue;
    out += "  <circle r=\"3\" fill=\"";
    out += style.stroke;
    out += "\" cx=\"";
    append_number(out, canvas.x(ring->front().x));
    out += "\" cy=\"";
    append_number(out, canvas.y(ring->front().y));
    out += "\"/>\n";
  }
}

std::vector<const Ring*> rings_of(const Polygon& p) {
  std::vector<const Ring*> rings;
  for (const Ring& r : p.rings) rings.push_back(&r);
  return rings;
}

void append_legend_item(std::string& out, double& x, double y, const std::string& swatch,
                        const std::string& label) {
  out += "  <g transform=\"translate(";
  append_number(out, x);
  out.push_back(' ');
  append_number(out, y);
  out += ")\">" + swatch + "<text x=\"22\" y=\"5\">" + label + "</text></g>\n";
  x += 34 + 7.2 * static_cast<double>(label.size());
}

std::string box_swatch(const Style& style) {
  std::string s = "<rect x=\"0\" y=\"-6\" width=\"16\" height=\"12\" fill=\"";
  s += style.fill;
  s += "\" fill-opacity=\"";
  append_number(s, std::max(style.fill_opacity, 0.4));
  s += "\" stroke=\"";
  s += style.stroke;
  s += "\"/>";
  return s;
}

}  // namespace

std::string write_svg(const Polygon& a, const Polygon& b, const Output& result) {
  // The result's region comes from its irreducible cycles (which also carry unbounded
  // results); the assembled polygons stand in when an Output has no cycles listed.
  std::vector<const Ring*> result_rings;
  for (const OutputIrreducible& p : result.irreducible) {
    if (p.vertices.size() >= 3) result_rings.push_back(&p.vertices);
  }
  if (result_rings.empty()) {
    for (const OgcPolygon& p : result.polygons) {
      result_rings.push_back(&p.shell);
      for (const Ring& h : p.holes) result_rings.push_back(&h);
    }
  }

  Canvas canvas;
  for (const Polygon* p : {&a, &b}) {
    for (const Ring& r : p->rings) {
      for (const Point& q : r) canvas.include(q);
    }
  }
  for (const Ring* r : result_rings) {
    for (const Point& q : *r) canvas.include(q);
  }
  for (const auto& [p, q] : result.dangling_edges) {
    canvas.include(p);
    canvas.include(q);
  }
  for (const Point& p : result.isolated_points) canvas.include(p);
  canvas.fit();

  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  append_number(out, canvas.width());
  out += "\" height=\"";
  append_number(out, canvas.height());
  out += "\" viewBox=\"0 0 ";
  append_number(out, canvas.width());
  out.push_back(' ');
  append_number(out, canvas.height());
  out += "\" font-family=\"sans-serif\" font-size=\"13\">\n";
  out += "  <title>mkbool: inputs A and B and the result</title>\n";
  out += "  <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";

  append_region(out, canvas, rings_of(a), a.type == PolygonType::hole, style_a, 1.5);
  append_region(out, canvas, rings_of(b), b.type == PolygonType::hole, style_b, 1.5);
  append_region(out, canvas, result_rings, result.unbounded, style_result, 2.5);

  for (const auto& [p, q] : result.dangling_edges) {
    out += "  <line stroke=\"";
    out += colour_dangling;
    out += "\" stroke-width=\"5\" stroke-linecap=\"round\" x1=\"";
    append_number(out, canvas.x(p.x));
    out += "\" y1=\"";
    append_number(out, canvas.y(p.y));
    out += "\" x2=\"";
    append_number(out, canvas.x(q.x));
    out += "\" y2=\"";
    append_number(out, canvas.y(q.y));
    out += "\"/>\n";
  }
  for (const Point& p : result.isolated_points) {
    out += "  <circle r=\"6\" stroke=\"white\" stroke-width=\"1.5\" fill=\"";
    out += colour_isolated;
    out += "\" cx=\"";
    append_number(out, canvas.x(p.x));
    out += "\" cy=\"";
    append_number(out, canvas.y(p.y));
    out += "\"/>\n";
  }

  const double legend_y = canvas.legend_top() + legend_height / 2;
  out += "  <line stroke=\"#999\" x1=\"0\" x2=\"100%\" y1=\"";
  append_number(out, canvas.legend_top());
  out += "\" y2=\"";
  append_number(out, canvas.legend_top());
  out += "\"/>\n";
  double x = 12;
  append_legend_item(out, x, legend_y, box_swatch(style_a),
                     a.type == PolygonType::hole ? "A (hole)" : "A");
  append_legend_item(out, x, legend_y, box_swatch(style_b),
                     b.type == PolygonType::hole ? "B (hole)" : "B");
  append_legend_item(out, x, legend_y, box_swatch(style_result),
                     result.unbounded ? "result (unbounded)" : "result");
  append_legend_item(out, x, legend_y,
                     std::string("<line x1=\"0\" x2=\"16\" y1=\"0\" y2=\"0\" stroke-width=\"5\" "
                                 "stroke-linecap=\"round\" stroke=\"") +
                         colour_dangling + "\"/>",
                     "dangling edge");
  append_legend_item(out, x, legend_y,
                     std::string("<circle cx=\"8\" cy=\"0\" r=\"6\" fill=\"") + colour_isolated + "\"/>",
                     "isolated point");
  out += "</svg>\n";
  return out;
}

}  // namespace mk
