// Shortest round-trip text of a double by Giulietti's Schubfach method. [Gi20] [IEEE754]
// Preconditions: see shortest_double.hpp.
//
// A double v = c 2^q (c < 2^53 an integer, q <= 0 on the path taken here) rounds back from
// every decimal inside its rounding interval [vl, vr] = [(c - 1/2) 2^q, (c + 1/2) 2^q], the
// lower half-gap 1/4 when c = 2^52 (the gap below a power of two is half the gap above);
// the interval is closed when c is even (ties round to even), open otherwise. With
// k = floor(log10 of the interval's width), the width is at least 10^k and below 10^(k+1):
// a decimal d 10^k with d = floor(v 10^-k) or d + 1 lies inside, and one digit fewer is
// possible only for the single multiple of 10 the interval can hold [Gi20]. v 10^-k and
// the interval's ends are computed as g (c << 2 << h) / 2^127 with g = 10^-k 2^(125 -
// floor(log2 10^-k)) when that is an integer and its floor + 1 otherwise (126 bits), rounded
// to odd, which compares with multiples of 4 as the exact values do [Gi20]. std::to_chars's choice of digits is the same (shortest,
// then nearest to v, ties to an even last digit), and tests/io/shortest_double_test.cpp
// checks the bytes against it.
#include "io/shortest_double.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

namespace mk::io_detail {

namespace {

using u64 = std::uint64_t;
__extension__ typedef unsigned __int128 u128;

// Decimal exponents -m for m in [0, kMaxM] and binary exponents q in [-kMaxQ, 0].
constexpr int kMaxM = 325;
constexpr int kMaxQ = 1074;

struct Tables {
  std::array<u64, kMaxM + 1> g_hi{}, g_lo{};  // g(m) = 10^m 2^(125 - beta(m)) if an integer, else its floor + 1
  std::array<int, kMaxM + 1> beta{};          // floor(log2 10^m)
  std::array<short, kMaxQ + 1> m_sym{};       // -floor(log10 2^q) for q = -index
  std::array<short, kMaxQ + 1> m_asym{};      // -floor(log10 (3/4) 2^q)
};

// The tables from 10^m in 32-bit limbs, exactly, when compiling: no floating-point logarithm
// and no transcribed constants.
constexpr Tables make_tables() {
  Tables t;
  constexpr int kLimbs = 36;  // 3 10^325 < 2^1082
  std::array<std::uint32_t, kLimbs> p{};
  p[0] = 1;
  const auto bit_length = [](const std::array<std::uint32_t, kLimbs>& x) {
    for (int i = kLimbs - 1; i >= 0; --i) {
      if (x[static_cast<std::size_t>(i)] != 0) return 32 * i + static_cast<int>(std::bit_width(x[static_cast<std::size_t>(i)]));
    }
    return 0;
  };
  const auto times = [](std::array<std::uint32_t, kLimbs> x, u64 factor) {
    u64 carry = 0;
    for (auto& limb : x) {
      const u64 y = limb * factor + carry;
      limb = static_cast<std::uint32_t>(y);
      carry = y >> 32;
    }
    return x;
  };
  std::array<int, kMaxM + 1> bits{}, bits3{};  // bit lengths of 10^m and 3 10^m
  for (int m = 0; m <= kMaxM; ++m) {
    if (m > 0) p = times(p, 10);
    const auto um = static_cast<std::size_t>(m);
    bits[um] = bit_length(p);
    bits3[um] = bit_length(times(p, 3));
    const int beta = bits[um] - 1;
    t.beta[um] = beta;
    u64 hi = 0, lo = 0;
    for (int j = 0; j < 126; ++j) {  // bit j of floor(10^m 2^(125 - beta)) is bit beta - 125 + j of 10^m
      const int i = beta - 125 + j;
      const u64 bit = i < 0 ? 0 : (p[static_cast<std::size_t>(i / 32)] >> (i % 32)) & 1;
      if (j < 64) {
        lo |= bit << j;
      } else {
        hi |= bit << (j - 64);
      }
    }
    // 10^m has m trailing zero bits: with no bit cut off g is exact, which keeps exact ties
    // (v 10^-k halfway between two integers, possible for m < 23 only) exact.
    if (beta - 125 > m) {
      lo += 1;
      hi += lo == 0 ? 1 : 0;
    }
    t.g_hi[um] = hi;
    t.g_lo[um] = lo;
  }
  // 10^-m <= 2^-n  iff  10^m >= 2^n  iff  bit_length(10^m) >= n + 1; the smallest such m.
  // 10^-m <= 3 2^(-n-2)  iff  bit_length(3 10^m) >= n + 3.
  int m = 0, m3 = 0;
  for (int n = 0; n <= kMaxQ; ++n) {
    while (bits[static_cast<std::size_t>(m)] < n + 1) ++m;
    while (bits3[static_cast<std::size_t>(m3)] < n + 3) ++m3;
    t.m_sym[static_cast<std::size_t>(n)] = static_cast<short>(m);
    t.m_asym[static_cast<std::size_t>(n)] = static_cast<short>(m3);
  }
  return t;
}

constexpr Tables kTables = make_tables();

// g(m) cp / 2^127 rounded to odd: the floor, its last bit set when anything was cut off.
u64 round_to_odd(std::size_t m, u64 cp) {
  const u128 low = static_cast<u128>(kTables.g_lo[m]) * cp;
  const u128 high = static_cast<u128>(kTables.g_hi[m]) * cp + (low >> 64);
  const u64 cut = (static_cast<u64>(high) & ((u64{1} << 63) - 1)) | static_cast<u64>(low);
  return static_cast<u64>(high >> 63) | (cut != 0 ? 1 : 0);
}

struct Decimal {
  u64 digits;
  int exponent;  // the value is digits 10^exponent
};

// The shortest decimal in the rounding interval of c 2^q (c >= 2^52, -1074 <= q <= 0), the
// nearest to it among those, ties to even.
Decimal shortest_decimal(u64 c, int q, bool asymmetric) {
  const auto n = static_cast<std::size_t>(-q);
  const auto m = static_cast<std::size_t>(asymmetric ? kTables.m_asym[n] : kTables.m_sym[n]);
  const int h = q + kTables.beta[m] + 2;  // g (c << 2 << h) / 2^127 is 4 c 2^q 10^m
  const u64 open = c & 1;                 // an odd c's interval leaves out its ends
  const u64 cb = c << 2;
  const u64 cbl = asymmetric ? cb - 1 : cb - 2;
  const u64 cbr = cb + 2;
  const u64 vb = round_to_odd(m, cb << h);
  const u64 vbl = round_to_odd(m, cbl << h);
  const u64 vbr = round_to_odd(m, cbr << h);
  const u64 s = vb >> 2;
  // One digit fewer: the interval, under 10 units of 10^k wide, holds one multiple of 10 at most.
  const u64 sp10 = s / 10 * 10;
  const u64 tp10 = sp10 + 10;
  const bool sp10_in = vbl + open <= sp10 << 2;
  const bool tp10_in = (tp10 << 2) + open <= vbr;
  // Else s or s + 1, whichever is inside; both: the nearer to v (vb is odd unless exact, so a
  // tie is exact), ties to even. Selected without branches: which way is a coin toss.
  const u64 t = s + 1;
  const bool s_in = vbl + open <= s << 2;
  const bool t_in = (t << 2) + open <= vbr;
  const u64 middle = (s + t) << 1;
  const bool nearer_s = vb < middle || (vb == middle && (s & 1) == 0);
  const u64 same_length = s_in && (!t_in || nearer_s) ? s : t;
  const u64 shorter = sp10_in ? sp10 : tp10;
  return {sp10_in != tp10_in ? shorter : same_length, -static_cast<int>(m)};
}

// The eight decimal digits of x < 10^8 as bytes 0-9, the first in the lowest byte: halves,
// quarters and single digits split in the lanes of one register (each quotient by a
// multiply and a shift, exact below the lanes' bounds: 10^4 for / 100, 100 for / 10).
u64 eight_digits(u64 x) {
  const u64 v = x / 10000 | (x % 10000) << 32;
  const u64 hundreds = ((v * 10486) >> 20) & 0x0000007F0000007F;
  const u64 pairs = hundreds | (v - hundreds * 100) << 16;
  const u64 tens = ((pairs * 103) >> 10) & 0x000F000F000F000F;
  return tens | (pairs - tens * 10) << 8;
}

void store16(char* out, u128 bytes) { std::memcpy(out, &bytes, 16); }

constexpr u64 kAsciiZeros = 0x3030303030303030;
constexpr u128 kAsciiZeros128 = static_cast<u128>(kAsciiZeros) << 64 | kAsciiZeros;

// digits 10^exponent (0 < digits < 10^17) as std::to_chars writes it: fixed notation
// unless scientific is shorter, trailing zeros of `digits` moved into the exponent. The
// digits stay in registers and leave in overlapping 16-byte stores (copies through memory
// of a variable size cost as much as finding the digits).
char* write_decimal(char* out, u64 digits, int exponent) {
  const u64 top = digits / 10'000'000'000'000'000;
  const u64 rest = digits - top * 10'000'000'000'000'000;
  const u64 a = eight_digits(rest / 100'000'000), b = eight_digits(rest % 100'000'000);
  // Of the 17 places top, a, b: zeros before the first digit and after the last nonzero one.
  const int lead = top != 0 ? 0 : a != 0 ? 1 + std::countr_zero(a) / 8 : 9 + std::countr_zero(b) / 8;
  const int trail = b != 0 ? std::countl_zero(b) / 8 : a != 0 ? 8 + std::countl_zero(a) / 8 : 16;
  const int n = 17 - lead - trail;
  exponent += trail;
  // The first digit, and the next ones in the bytes of `more` (only its first n - 1 are written).
  const u128 ab = static_cast<u128>(b) << 64 | a;
  char first;
  u128 more;
  if (lead == 0) {
    first = static_cast<char>('0' + top);
    more = ab;
  } else {
    const u128 from_first = ab >> (8 * (lead - 1));
    first = static_cast<char>('0' + static_cast<int>(from_first & 0xff));
    more = from_first >> 8;
  }
  more |= kAsciiZeros128;
  const int e10 = n - 1 + exponent;  // scientific notation's exponent
  const int fixed_size = exponent >= 0 ? n + exponent : n + exponent > 0 ? n + 1 : 2 - exponent;
  const int scientific_size = n + (n > 1 ? 1 : 0) + 2 + (e10 >= 100 || e10 <= -100 ? 3 : 2);
  if (fixed_size <= scientific_size) {  // then fixed_size <= 23
    if (exponent >= 0) {                // digits, then up to 22 zeros
      out[0] = first;
      store16(out + 1, more);
      store16(out + n, kAsciiZeros128);
      store16(out + n + 16, kAsciiZeros128);
    } else if (n + exponent > 0) {  // the point after `whole` digits, 1 <= whole < n
      const int whole = n + exponent;
      out[0] = first;
      store16(out + 1, more);
      store16(out + whole + 1, more >> (8 * (whole - 1)));
      out[whole] = '.';
    } else {  // "0.", up to 20 zeros, the digits
      const int zeros = -exponent - n;
      store16(out, kAsciiZeros128);
      store16(out + 16, kAsciiZeros128);
      out[1] = '.';
      out[2 + zeros] = first;
      store16(out + 3 + zeros, more);
    }
    return out + fixed_size;
  }
  out[0] = first;
  char* p = out + 1;
  if (n > 1) {
    out[1] = '.';
    store16(out + 2, more);
    p = out + n + 1;
  }
  *p++ = 'e';
  *p++ = e10 < 0 ? '-' : '+';
  int e = e10 < 0 ? -e10 : e10;
  if (e >= 100) {
    *p++ = static_cast<char>('0' + e / 100);
    e %= 100;
  }
  p[0] = static_cast<char>('0' + e / 10);
  p[1] = static_cast<char>('0' + e % 10);
  return p + 2;
}

}  // namespace

char* write_shortest(char* out, double v) {
  const auto bits = std::bit_cast<u64>(v);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  // Zero, subnormals (biased 0), and 2^53 or more (q > 0), infinities and NaN: the library.
  if (biased == 0 || biased > 1075) return std::to_chars(out, out + kShortestDoubleRoom, v).ptr;
  if (bits >> 63) *out++ = '-';
  const u64 fraction = bits & ((u64{1} << 52) - 1);
  const u64 c = (u64{1} << 52) | fraction;
  const int q = biased - 1075;
  Decimal d;
  if (q >= -52 && (c & ((u64{1} << -q) - 1)) == 0) {
    d = {c >> -q, 0};  // an integer below 2^53: its own digits are the shortest
  } else {
    d = shortest_decimal(c, q, fraction == 0 && biased > 1);
  }
  return write_decimal(out, d.digits, d.exponent);
}

}  // namespace mk::io_detail
