// Tests of the SVG picture: elements present, y axis pointing up, shading of unbounded
// results, distinct pixels for ulp-scale inputs. Writes examples for a person to look at.
// [MK89 §2.2]
// Preconditions: none.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "io/svg.hpp"

namespace mk {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

// The cy attributes of the isolated points' dots, in document order.
std::vector<double> circle_ys(const std::string& svg) {
  std::vector<double> ys;
  const std::regex cy("<circle r=\"6\"[^>]* cy=\"([-0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), cy); it != std::sregex_iterator(); ++it) {
    ys.push_back(std::stod((*it)[1]));
  }
  return ys;
}

Output sample_output() {
  Output out;
  out.irreducible.push_back({{{2, 2}, {4, 2}, {4, 4}, {2, 4}}, {}, PolygonType::island});
  out.irreducible.push_back({{{2.5, 2.5}, {2.5, 3}, {3, 3}}, {}, PolygonType::hole});
  out.dangling_edges = {{{4, 4}, {6, 4}}};
  out.isolated_points = {{0, 0}, {0, 6}};
  return out;
}

void save(const std::string& name, const std::string& svg) {
  std::ofstream(name) << svg;  // in the test's working directory, for eyeballing
}

TEST(ioSvg, DrawsInputsResultAndLegend) {
  const Polygon a{{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, PolygonType::island};
  const Polygon b{{{{2, 2}, {6, 2}, {6, 6}, {2, 6}}}, PolygonType::island};
  const std::string svg = write_svg(a, b, sample_output());
  save("io_svg_example.svg", svg);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("viewBox=\"0 0 "), std::string::npos);
  EXPECT_EQ(count(svg, "fill-rule=\"evenodd\""), 3u);  // A, B, result
  EXPECT_EQ(count(svg, "stroke-width=\"5\" stroke-linecap=\"round\" x1="), 1u);  // dangling edge
  EXPECT_EQ(count(svg, "<circle r=\"6\""), 2u);  // isolated points
  for (const char* label : {">A<", ">B<", ">result<", ">dangling edge<", ">isolated point<"}) {
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  }
  EXPECT_EQ(count(svg, "<"), count(svg, ">"));
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(ioSvg, YAxisPointsUp) {
  const std::vector<double> ys = circle_ys(write_svg(Polygon{}, Polygon{}, sample_output()));
  ASSERT_GE(ys.size(), 2u);
  EXPECT_GT(ys[0], ys[1]);  // (0, 0) is drawn below (0, 6)
}

TEST(ioSvg, UnboundedResultAndHoleInputsShadeTheOutside) {
  Output out;
  out.unbounded = true;
  out.irreducible.push_back({{{0, 0}, {0, 1}, {1, 1}, {1, 0}}, {}, PolygonType::hole});
  const Polygon hole{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, PolygonType::hole};
  const std::string svg = write_svg(hole, hole, out);
  save("io_svg_unbounded.svg", svg);
  EXPECT_EQ(count(svg, "d=\"M0 0 H"), 3u);  // the canvas subpath in A, B and the result
  EXPECT_NE(svg.find(">result (unbounded)<"), std::string::npos);
  EXPECT_NE(svg.find(">A (hole)<"), std::string::npos);
}

TEST(ioSvg, UlpScaleInputsStayApart) {
  const double one = 1.0, next = std::nextafter(1.0, 2.0);
  Output out;
  out.isolated_points = {{one, one}, {one, next}};
  const std::vector<double> ys = circle_ys(write_svg(Polygon{}, Polygon{}, out));
  ASSERT_EQ(ys.size(), 2u);
  EXPECT_GT(ys[0] - ys[1], 100.0);
}

TEST(ioSvg, DegenerateAndExtremeExtentsAreFinite) {
  const double big = 1.7976931348623157e308;
  for (const Output& out : {Output{}, [] {
                              Output o;
                              o.isolated_points = {{3, 3}};
                              return o;
                            }(),
                            [&] {
                              Output o;
                              o.dangling_edges = {{{-big, -big}, {big, 0}}};
                              return o;
                            }(),
                            [] {
                              Output o;
                              o.isolated_points = {{0, 0}, {4.9e-324, 0}};
                              return o;
                            }()}) {
    const std::string svg = write_svg(Polygon{}, Polygon{}, out);
    EXPECT_EQ(svg.find("nan"), std::string::npos) << svg;
    EXPECT_EQ(svg.find("inf"), std::string::npos) << svg;
  }
}

TEST(ioSvg, DegenerateInputRingsAreDrawn) {
  const Polygon a{{{{0, 0}, {4, 0}}, {{2, 3}}}, PolygonType::island};
  const std::string svg = write_svg(a, Polygon{}, Output{});
  EXPECT_NE(svg.find("<circle r=\"3\""), std::string::npos);  // the one-point ring
  EXPECT_NE(svg.find(" L"), std::string::npos);                // the two-point ring
}

}  // namespace
}  // namespace mk
