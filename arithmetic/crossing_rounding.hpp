// The nearest doubles to the crossing point of two segments, decided with exact floating-
// point expansions instead of rationals: the crossing is x = X / D with X = a0x D + N dax,
// N = (b0 - a0) x (b1 - b0), D = (a1 - a0) x (b1 - b0), all exact expansions of the input
// doubles, and a candidate double c is the nearest one exactly when the residual X - c D
// lies within half the gap from c to its neighbour, times D: the sign of one more exact
// expansion. [Sh97 §2] (expansions) [At20] (implicit points evaluated on demand)
// Preconditions: finite inputs; the segments cross properly (D != 0). Returns false, and
// the caller rounds the exact rational instead, when the magnitudes of the inputs or of the
// crossing are too far apart for the expansions to stay clear of underflow and overflow.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>

#include "arithmetic/expansion.hpp"
#include "kernel/point.hpp"

namespace mk {

namespace crossing_rounding {

// An expansion in a fixed buffer. The largest one built below is X, at most
// 2 |D| + 4 |N| <= 96 components (D and N have at most 16 each before compression).
struct Expansion {
  std::array<double, 160> c;  // not value-initialised: only c[0..n) is ever read
  std::size_t n = 0;
  std::span<const double> view() const { return {c.data(), n}; }
  std::span<double> room() { return {c.data(), c.size()}; }
};

inline void compress_in_place(Expansion& e) { e.n = expansion::compress(e.view(), e.room()); }

inline void negate(Expansion& e) {
  for (std::size_t i = 0; i < e.n; ++i) e.c[i] = -e.c[i];
}

// e1 * f where f = f.hi + f.lo is a two-component expansion (an exact difference).
inline Expansion times_two_term(const Expansion& e, expansion::TwoTerm f) {
  Expansion hi_part, lo_part, out;
  hi_part.n = expansion::scale_expansion(e.view(), f.hi, hi_part.room());
  if (f.lo == 0.0) return hi_part;
  lo_part.n = expansion::scale_expansion(e.view(), f.lo, lo_part.room());
  out.n = expansion::expansion_sum(hi_part.view(), lo_part.view(), out.room());
  return out;
}

inline Expansion of_two_term(expansion::TwoTerm t) {
  Expansion e;
  if (t.lo != 0.0) e.c[e.n++] = t.lo;
  e.c[e.n++] = t.hi;
  return e;
}

// u x v = u.x v.y - u.y v.x for vectors of exact differences, as a compressed expansion.
inline Expansion cross(expansion::TwoTerm ux, expansion::TwoTerm uy, expansion::TwoTerm vx, expansion::TwoTerm vy) {
  Expansion left = times_two_term(of_two_term(ux), vy);
  Expansion right = times_two_term(of_two_term(uy), vx);
  negate(right);
  Expansion out;
  out.n = expansion::expansion_sum(left.view(), right.view(), out.room());
  compress_in_place(out);
  return out;
}

inline Expansion sum(const Expansion& a, const Expansion& b) {
  Expansion out;
  out.n = expansion::expansion_sum(a.view(), b.view(), out.room());
  return out;
}

inline Expansion scaled(const Expansion& e, double b) {
  Expansion out;
  out.n = expansion::scale_expansion(e.view(), b, out.room());
  return out;
}

// Exponent of the unit in the last place of a non-zero double: every multiple of it is a
// multiple of 2^granularity(v).
inline int granularity(double v) { return std::ilogb(v) - 52; }

// Limits for the scaled problem. Inputs are scaled so that the largest has exponent 300;
// then |differences| < 2^302, |D|, |N| < 2^605 and |X| < 2^908: no overflow. Every
// component is a multiple of the product of the factors' granularities; requiring those
// to stay at or above 2^-1000 keeps every error term of every two-sum and two-product
// representable (no underflow), which is all the expansion algorithms need [Sh97 §2].
inline constexpr int kTopExponent = 300;
inline constexpr int kFloor = -1000;

// The nearest double c to X / D for D > 0, starting from the estimate, and an estimate of
// the remainder X / D - c (relative error below 2^-40). `unit_d` is a lower bound of the
// granularity of the components of D.
inline bool nearest_quotient(const Expansion& x_num, const Expansion& d, int unit_d, double& out, double& tail) {
  double c = expansion::estimate(x_num.view()) / expansion::estimate(d.view());
  if (!std::isfinite(c)) return false;
  const double d_est = expansion::estimate(d.view());
  for (int attempt = 0; attempt < 4; ++attempt) {
    if (c == 0.0) {
      // X itself decides whether the crossing is exactly 0; a non-zero value this close to
      // zero is beyond the range handled here.
      if (expansion::sign(x_num.view()) == 0) {
        out = 0.0;
        tail = 0.0;
        return true;
      }
      return false;
    }
    // The half gaps below and above c, as powers of two: at a power of two the gap below
    // is half the gap above.
    const int g = granularity(c);
    const bool at_binade_start = std::fabs(c) == std::ldexp(1.0, std::ilogb(c));
    const int half_up_exp = g - 1;                                   // above |c|
    const int half_down_exp = at_binade_start ? g - 2 : g - 1;       // below |c|
    if (g + unit_d < kFloor || half_down_exp + unit_d < kFloor) return false;
    // R = X - c D, exactly.
    Expansion cd = scaled(d, -c);
    Expansion r = sum(x_num, cd);
    compress_in_place(r);
    const int rs = expansion::sign(r.view());
    if (rs == 0) {
      out = c;  // the crossing is exactly c
      tail = 0.0;
      return true;
    }
    // X / D - c = R / D; both estimates within 2^-44 relative, the quotient within 2^-42.
    const double r_over_d = expansion::estimate(r.view()) / d_est;
    // Toward +infinity when R > 0 (D > 0): compare R with the half gap on that side. For
    // negative c the gap above |c| lies toward -infinity.
    const bool toward_larger_magnitude = (rs > 0) == (c > 0);
    const int half_exp = toward_larger_magnitude ? half_up_exp : half_down_exp;
    const double half = std::ldexp(1.0, half_exp);
    // Filter: the estimates of R and D carry relative errors below 2^-44 (at most 160
    // non-overlapping components, each partial sum within twice the value).
    const double r_est = std::fabs(expansion::estimate(r.view()));
    const double limit = half * d_est;
    constexpr double margin = 0x1p-40;
    if (r_est * (1 + margin) < limit * (1 - margin)) {
      out = c;
      tail = r_over_d;
      return true;
    }
    // Exactly: S = |R| - half D.
    if (rs < 0) negate(r);
    Expansion hd = scaled(d, -half);  // exact: a power of two, above the floor (checked)
    Expansion s = sum(r, hd);
    const int ss = expansion::sign(s.view());
    const double neighbour = std::nextafter(c, rs > 0 ? HUGE_VAL : -HUGE_VAL);
    if (ss < 0) {
      out = c;
      tail = r_over_d;
      return true;
    }
    if (ss == 0) {  // a tie: the neighbour with an even last significand bit
      const double m = std::ldexp(c, -g);  // the integer significand of c, exactly
      out = std::fmod(m, 2.0) == 0.0 ? c : neighbour;
      tail = out == c ? half * rs : -half * rs;  // exactly half a gap
      return true;
    }
    c = neighbour;
  }
  return false;
}

}  // namespace crossing_rounding

// The nearest doubles (ties to even) to the crossing point of segments a0a1 and b0b1, which
// cross properly. Returns false when the inputs are out of this method's range (magnitudes
// more than about 2^330 apart, or a crossing point far smaller than the inputs, or one in
// the subnormal range); the caller then rounds the exact rational. With `tail`, also an
// estimate of the exact crossing minus `out`, per axis, within 2^-40 of its magnitude
// plus 2^-1074 (what the area's filtered sum needs).
inline bool nearest_crossing(const Point& a0, const Point& a1, const Point& b0, const Point& b1, Point& out,
                             Point* tail = nullptr) {
  using namespace crossing_rounding;
  const std::array<double, 8> in{a0.x, a0.y, a1.x, a1.y, b0.x, b0.y, b1.x, b1.y};
  int top = -100000;
  int unit = 100000;
  for (const double v : in) {
    if (v == 0.0) continue;
    top = std::max(top, std::ilogb(v));
    unit = std::min(unit, granularity(v));
  }
  if (top == -100000) return false;  // all zero: no proper crossing
  const int shift = kTopExponent - top;
  // Differences are multiples of 2^(unit + shift); D and N of twice that, X of three times.
  const int unit_s = unit + shift;
  if (3 * unit_s < kFloor) return false;
  std::array<double, 8> s{};
  for (std::size_t i = 0; i < 8; ++i) s[i] = std::ldexp(in[i], shift);  // exact: stays normal
  const auto diff = [](double a, double b) { return expansion::two_diff(a, b); };
  const expansion::TwoTerm dax = diff(s[2], s[0]), day = diff(s[3], s[1]);
  const expansion::TwoTerm dbx = diff(s[6], s[4]), dby = diff(s[7], s[5]);
  const expansion::TwoTerm wx = diff(s[4], s[0]), wy = diff(s[5], s[1]);
  Expansion d = cross(dax, day, dbx, dby);
  Expansion n = cross(wx, wy, dbx, dby);
  const int ds = expansion::sign(d.view());
  if (ds == 0) return false;  // parallel: not a proper crossing
  if (ds < 0) {
    negate(d);
    negate(n);
  }
  const int unit_d = 2 * unit_s;
  // X = a0 D + N da, per axis; t = N / D is the parameter along a.
  Expansion x_num = sum(scaled(d, s[0]), times_two_term(n, dax));
  Expansion y_num = sum(scaled(d, s[1]), times_two_term(n, day));
  compress_in_place(x_num);
  compress_in_place(y_num);
  double cx = 0, cy = 0, tx = 0, ty = 0;
  if (!nearest_quotient(x_num, d, unit_d, cx, tx) || !nearest_quotient(y_num, d, unit_d, cy, ty)) return false;
  // Back to the input's scale: exact, and the same rounding, unless the result falls where
  // doubles are spaced differently (the subnormal range).
  const double rx = std::ldexp(cx, -shift);
  const double ry = std::ldexp(cy, -shift);
  constexpr double safe = 0x1p-1020;
  if ((rx != 0.0 && std::fabs(rx) < safe) || (ry != 0.0 && std::fabs(ry) < safe)) return false;
  out = {rx, ry};
  if (tail) *tail = {std::ldexp(tx, -shift), std::ldexp(ty, -shift)};
  return true;
}

}  // namespace mk
