// A 100 MB input through the command (issue 3, bad input): read, computed and written in
// time proportional to its size, and a 100 MB input with an error at its very end refused
// with the position of the error. [OGC06-103 §7] [MK89 §4.3] (near-linear work)
// Preconditions: about 3 GB of memory and 100 MB in the temporary directory; labelled
// `slow`. The time is printed, and the limit only catches hangs and quadratic behaviour.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <string>

#include "tests/cli/cli_support.hpp"

namespace mk::test {
namespace {

constexpr std::size_t target_bytes = 100u << 20;

void append_vertex(std::string& out, double x, double y) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  *r.ptr++ = ' ';
  r = std::to_chars(r.ptr, buf + sizeof buf, y);
  out.append(buf, r.ptr);
}

// A comb: the shell runs along y = 0, then back along a zigzag between y = 1.25 and 1.75
// with a tooth every 0.125 in x (millions of vertices, all edges short in x, so a sweep
// sees few at a time). `closing` is the last vertex: (0 0) closes the ring.
std::string comb(std::size_t& vertices, const char* closing) {
  std::string text;
  text.reserve(target_bytes + 4096);
  text += "POLYGON ((0 0, ";
  std::size_t n = 0;
  double x = 0;
  for (; text.size() < target_bytes; x += 0.125, ++n) {
    append_vertex(text, x, n % 2 == 0 ? 1.25 : 1.75);
    text += ", ";
  }
  append_vertex(text, x, 0);
  text += ", ";
  text += closing;
  text += "))";
  vertices = n + 2;
  return text;
}

TEST(cliLargeInput, HundredMegabytePolygonIsComputed) {
  TempDir dir;
  std::size_t vertices = 0;
  const std::string path = dir.write("comb.wkt", comb(vertices, "0 0"));
  // B cuts the teeth of the first 20000 units at y = 1.5: 160000 crossings, and the area is
  // 20000 * (1.375 + 1.5) / 2 exactly.
  const auto start = std::chrono::steady_clock::now();
  const ProcessResult r = run_mkbool({"intersection", path, "POLYGON((0 -3,20000 -3,20000 1.5,0 1.5,0 -3))", "--stats",
                                      "-o", dir.file("out.wkt")},
                                     {}, std::chrono::seconds(300));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("mkbool on %zu MB of WKT (%zu vertices): %.1f s, stats %s\n", target_bytes >> 20, vertices, seconds,
              r.err.c_str());
  ASSERT_FALSE(r.timed_out) << "more than 300 s for 100 MB: not linear";
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto stats = nlohmann::json::parse(r.err);
  EXPECT_EQ(stats["vertices_in"], vertices + 4);
  EXPECT_EQ(stats["area_exact"], "28750");
  EXPECT_EQ(stats["rounded_valid"], true);
}

TEST(cliLargeInput, HundredMegabyteInputWithAnErrorAtTheEndIsRefusedWithItsPosition) {
  TempDir dir;
  std::size_t vertices = 0;
  const std::string path = dir.write("unclosed.wkt", comb(vertices, "0 1"));
  const ProcessResult r = run_mkbool({"intersection", path, "POLYGON EMPTY", "-o", dir.file("out.wkt")}, {},
                                     std::chrono::seconds(120));
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_NE(r.err.find("WKT line 1, column "), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("vertex " + std::to_string(vertices) + "): ring is not closed"), std::string::npos)
      << describe(r);
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.wkt")));
}

}  // namespace
}  // namespace mk::test
