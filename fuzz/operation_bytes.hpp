// The byte format of the whole-operation fuzz target: two polygons of the paper's model (rings
// of any length, island or hole), decoded from arbitrary bytes so that small inputs reach the
// degenerate configurations (shared vertices, collinear edges, vertices on edges, repeated
// points) and the ends of the double range; and its encoder, which turns the experiment
// generators' cases into seeds. [MK89 §2.2] (polygon model) [BRIEF §8] (hostile input)
// Preconditions: none; every byte string decodes to two polygons with finite coordinates.
#pragma once

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "core/polygon.hpp"

namespace mk::fuzz {

// Layout: a flags byte (bit 0: A is a hole, bit 1: B is a hole, bits 2-3: operation, bit 4:
// non-regular), then A and B, each: a ring count byte (mod 5), and per ring a vertex count
// byte (mod 33) and its vertices. A vertex is a tag byte and its payload:
//   tag % 4 == 0: two signed bytes, each a lattice coordinate in [-8, 8) (degeneracies)
//   tag % 4 == 1: two little-endian doubles (non-finite ones become 0)
//   tag % 4 == 2: two bytes, each an index into `extremes` (ends of the double range)
//   tag % 4 == 3: one byte, an earlier vertex of the same polygon to repeat (shared vertex)
// A truncated input ends where it ends.
inline constexpr std::array<double, 16> extremes = {
    0.0, DBL_MAX, -DBL_MAX, std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
    DBL_MIN, 1e300, -1e300, 1e154, 0x1p-1022 * 3, 1.0, -1.0, 0x1p1023, -0x1p1023, 0x1p-1074 * 2, 1e-300};

struct DecodedCase {
  Polygon a;
  Polygon b;
  Operation op = Operation::intersection;
  bool regular = true;
};

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool done() const { return pos_ >= size_; }
  std::uint8_t byte() { return done() ? 0 : data_[pos_++]; }
  double real() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(byte()) << (8 * i);
    double v = 0;
    std::memcpy(&v, &bits, sizeof v);
    return std::isfinite(v) ? v : 0.0;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

inline Polygon decode_polygon(ByteReader& in, bool hole) {
  Polygon p;
  p.type = hole ? PolygonType::hole : PolygonType::island;
  std::vector<Point> seen;
  const int rings = in.byte() % 5;
  for (int r = 0; r < rings && !in.done(); ++r) {
    Ring ring;
    const int n = in.byte() % 33;
    for (int v = 0; v < n && !in.done(); ++v) {
      const std::uint8_t tag = in.byte();
      Point q;
      switch (tag % 4) {
        case 0:
          q.x = static_cast<std::int8_t>(in.byte()) % 8;
          q.y = static_cast<std::int8_t>(in.byte()) % 8;
          break;
        case 1:
          q.x = in.real();
          q.y = in.real();
          break;
        case 2:
          q.x = extremes[in.byte() % extremes.size()];
          q.y = extremes[in.byte() % extremes.size()];
          break;
        default:
          if (seen.empty()) continue;
          q = seen[in.byte() % seen.size()];
      }
      if (q.x == 0) q.x = 0;  // one zero: -0 and 0 are the same coordinate
      if (q.y == 0) q.y = 0;
      ring.push_back(q);
      seen.push_back(q);
    }
    if (!ring.empty()) p.rings.push_back(std::move(ring));
  }
  return p;
}

inline DecodedCase decode_case(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  const std::uint8_t flags = in.byte();
  DecodedCase c;
  c.op = static_cast<Operation>((flags >> 2) & 3);
  c.regular = (flags & 16) == 0;
  c.a = decode_polygon(in, (flags & 1) != 0);
  c.b = decode_polygon(in, (flags & 2) != 0);
  return c;
}

// The bytes that decode to `a` and `b` (as far as the format carries them: at most 4 rings
// of at most 32 vertices each; the rest is cut off). Lattice points and the extremes are
// written in their short forms, every other coordinate as two doubles.
inline std::string encode_case(const Polygon& a, const Polygon& b, Operation op, bool regular) {
  std::string out;
  out.push_back(static_cast<char>((a.type == PolygonType::hole ? 1 : 0) | (b.type == PolygonType::hole ? 2 : 0) |
                                  (static_cast<int>(op) << 2) | (regular ? 0 : 16)));
  const auto put_double = [&](double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof v);
    for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((bits >> (8 * i)) & 0xff));
  };
  const auto lattice = [](double v) { return v == std::floor(v) && v >= -7 && v <= 7; };
  for (const Polygon* p : {&a, &b}) {
    const std::size_t rings = std::min<std::size_t>(p->rings.size(), 4);
    out.push_back(static_cast<char>(rings));
    for (std::size_t r = 0; r < rings; ++r) {
      const Ring& ring = p->rings[r];
      const std::size_t n = std::min<std::size_t>(ring.size(), 32);
      out.push_back(static_cast<char>(n));
      for (std::size_t v = 0; v < n; ++v) {
        const Point& q = ring[v];
        if (lattice(q.x) && lattice(q.y)) {
          out.push_back(0);
          out.push_back(static_cast<char>(static_cast<std::int8_t>(q.x)));
          out.push_back(static_cast<char>(static_cast<std::int8_t>(q.y)));
        } else {
          out.push_back(1);
          put_double(q.x);
          put_double(q.y);
        }
      }
    }
  }
  return out;
}

}  // namespace mk::fuzz
