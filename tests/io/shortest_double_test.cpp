// Tests of the shortest round-trip writer of doubles: the same bytes as std::to_chars (the
// shortest digits, the nearest among them, ties to even, fixed or scientific notation) on
// every binade's edges, powers of ten, integers, exact ties and random doubles, and its
// stores within their room. [Gi20] [IEEE754]
// Preconditions: none.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "io/shortest_double.hpp"

namespace mk {
namespace {

using io_detail::kShortestDoubleMaxChars;
using io_detail::kShortestDoubleRoom;
using io_detail::write_shortest;

std::string library_text(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// The text, checking that nothing past the room was written and the text fits its bound.
std::string our_text(double v) {
  constexpr int kGuard = 16;
  char buf[kShortestDoubleRoom + kGuard];
  std::memset(buf, '#', sizeof buf);
  const char* end = write_shortest(buf, v);
  for (int i = kShortestDoubleRoom; i < kShortestDoubleRoom + kGuard; ++i) EXPECT_EQ(buf[i], '#') << "wrote past its room";
  EXPECT_LE(end - buf, kShortestDoubleMaxChars);
  return std::string(buf, static_cast<std::size_t>(end - buf));
}

// Counts the values whose text differs from the library's; prints the first few.
class Comparison {
 public:
  void check(double v) {
    const std::string expected = library_text(v), actual = our_text(v);
    if (expected == actual) return;
    if (++mismatches_ <= 10) ADD_FAILURE() << std::hexfloat << v << ": expected " << expected << ", got " << actual;
  }
  int mismatches() const { return mismatches_; }

 private:
  int mismatches_ = 0;
};

TEST(ioShortestDouble, SmallCases) {
  EXPECT_EQ(our_text(0.1), "0.1");
  EXPECT_EQ(our_text(-2.5), "-2.5");
  EXPECT_EQ(our_text(100), "100");
  EXPECT_EQ(our_text(1e6), "1e+06");
  EXPECT_EQ(our_text(123456.0), "123456");
  EXPECT_EQ(our_text(0.001), "0.001");
  EXPECT_EQ(our_text(1e-5), "1e-05");
  EXPECT_EQ(our_text(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(our_text(0.0), "0");
  EXPECT_EQ(our_text(-0.0), "-0");  // as std::to_chars: the writers map -0 to 0 themselves
  // c 2^q exactly halfway between the two shortest candidates: the even one.
  EXPECT_EQ(our_text(1238149735313913.25), "1238149735313913.2");
  EXPECT_EQ(our_text(std::numeric_limits<double>::max()), library_text(std::numeric_limits<double>::max()));
  EXPECT_EQ(our_text(std::numeric_limits<double>::denorm_min()), "5e-324");
}

TEST(ioShortestDouble, EveryBinadeEdgeAndPowerOfTen) {
  Comparison c;
  for (int e = -1074; e <= 1023; ++e) {
    const double p = std::ldexp(1.0, e);
    for (const double v : {p, std::nextafter(p, 0.0), std::nextafter(p, 2 * p), 3 * p, -p}) c.check(v);
  }
  for (int e = -325; e <= 308; ++e) {
    const double p = std::pow(10.0, e);
    for (int k = 1; k < 10; ++k) {
      const double v = k * p;
      if (std::isfinite(v)) {
        c.check(v);
        c.check(std::nextafter(v, 0.0));
        c.check(std::nextafter(v, 2 * v));
      }
    }
  }
  EXPECT_EQ(c.mismatches(), 0);
}

TEST(ioShortestDouble, IntegersAndShortFractions) {
  Comparison c;
  for (std::int64_t i = -100000; i <= 100000; ++i) {
    const auto d = static_cast<double>(i);
    for (const double v : {d, d / 8, d / 10, d / 1000, d * 1e10 + 0.5, d * 8.0e10 + 0.25}) c.check(v);
  }
  for (std::int64_t i = (std::int64_t{1} << 53) - 100000; i <= (std::int64_t{1} << 53) + 100000; ++i) {
    c.check(static_cast<double>(i));
  }
  EXPECT_EQ(c.mismatches(), 0);
}

TEST(ioShortestDouble, RandomDoublesAsTheLibraryWritesThem) {
  const std::uint64_t seed = std::random_device{}();
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  Comparison c;
  std::uniform_real_distribution<double> coordinate(-1000, 1000);
  std::uniform_int_distribution<int> exponent(-80, 80);
  for (int i = 0; i < 1'000'000; ++i) {
    const double bits = std::bit_cast<double>(rng());
    if (std::isfinite(bits)) c.check(bits);
    c.check(coordinate(rng));
    c.check(std::ldexp(static_cast<double>(rng() >> 11), exponent(rng)));  // any mantissa, common scales
    c.check(std::ldexp(static_cast<double>(rng() >> 40), exponent(rng)));  // short mantissas: ties, zeros
  }
  EXPECT_EQ(c.mismatches(), 0) << "seed " << seed;
}

}  // namespace
}  // namespace mk
