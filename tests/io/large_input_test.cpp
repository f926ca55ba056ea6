// A 100 MB generated WKT input is read completely (linear time and memory, no recursion),
// and hostile large inputs fail fast with short messages. [OGC06-103 §7]
// Preconditions: about 0.5 GB of memory. Not a timed assertion: the time is printed.
#include <gtest/gtest.h>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "io/wkt.hpp"

namespace mk {
namespace {

constexpr std::size_t target_bytes = 100u << 20;

void append_vertex(std::string& out, double x, double y) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  *r.ptr++ = ' ';
  r = std::to_chars(r.ptr, buf + sizeof buf, y);
  out.append(buf, r.ptr);
}

// Half the bytes: one polygon whose shell has millions of vertices (a zigzag along x);
// the other half: a MULTIPOLYGON of many small triangles.
std::string generate(std::size_t& expected_vertices, std::size_t& expected_polygons) {
  std::string text;
  text.reserve(target_bytes + (1u << 20));
  text += "GEOMETRYCOLLECTION (POLYGON ((";
  std::size_t n = 0;
  for (double x = 0; text.size() < target_bytes / 2; x += 0.125) {
    append_vertex(text, x, (n % 2 == 0) ? 0.7853981633974483 : 1.5707963267948966);
    text += ", ";
    ++n;
  }
  text += "-1 -1, 0 0.7853981633974483)), MULTIPOLYGON (";
  expected_vertices = n + 1;
  expected_polygons = 1;
  for (std::size_t i = 0; text.size() < target_bytes; ++i) {
    if (i > 0) text += ", ";
    const double x = static_cast<double>(i) * 3.0000001;
    text += "((";
    append_vertex(text, x, -2);
    text += ", ";
    append_vertex(text, x + 1.5, -2);
    text += ", ";
    append_vertex(text, x, -0.5);
    text += ", ";
    append_vertex(text, x, -2);
    text += "))";
    expected_vertices += 3;
    ++expected_polygons;
  }
  text += "))";
  return text;
}

TEST(ioLargeInput, Reads100MegabytesOfWkt) {
  std::size_t expected_vertices = 0, expected_polygons = 0;
  const std::string text = generate(expected_vertices, expected_polygons);
  const auto start = std::chrono::steady_clock::now();
  const MultiPolygon mp = read_wkt(text);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("read %.1f MB of WKT (%zu vertices, %zu polygons) in %.2f s\n",
              static_cast<double>(text.size()) / (1 << 20), expected_vertices, expected_polygons,
              seconds);
  ASSERT_EQ(mp.size(), expected_polygons);
  std::size_t vertices = 0;
  for (const OgcPolygon& p : mp) vertices += p.shell.size();
  EXPECT_EQ(vertices, expected_vertices);
}

TEST(ioLargeInput, HostileInputsFailFastWithShortMessages) {
  const std::string parens = "GEOMETRYCOLLECTION (" + std::string(50u << 20, '(');
  const std::string digits = "POLYGON ((" + std::string(50u << 20, '1') + "x";
  const std::string spaces = std::string(50u << 20, '\n') + "POLYGON ((0 0, nan 0))";
  for (const std::string* text : {&parens, &digits, &spaces}) {
    try {
      read_wkt(*text);
      ADD_FAILURE() << "accepted";
    } catch (const InvalidInput& e) {
      EXPECT_LT(std::string(e.what()).size(), 200u) << e.what();
    }
  }
}

}  // namespace
}  // namespace mk
