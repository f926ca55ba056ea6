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
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
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

// The binary exponent of a non-zero double (std::ilogb), from its bits when it is normal.
inline int exponent(double v) {
  const int field = static_cast<int>((std::bit_cast<std::uint64_t>(v) >> 52) & 0x7ff);
  return field != 0 ? field - 1023 : std::ilogb(v);
}

// 2^k as a double (std::ldexp(1, k)), from its bits in the normal range.
inline double power_of_two(int k) {
  if (k >= -1022 && k <= 1023) return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
  return std::ldexp(1.0, k);
}

// v * 2^k, exact when the result is normal (std::ldexp without the library call).
inline double times_power_of_two(double v, int k) {
  if (k >= -1022 && k <= 1023) return v * power_of_two(k);
  return std::ldexp(v, k);
}

// Exponent of the unit in the last place of a non-zero double: every multiple of it is a
// multiple of 2^granularity(v).
inline int granularity(double v) { return exponent(v) - 52; }

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


// ---- The floating-point filter ----------------------------------------------------------
// Before any expansion: D, N and the residual R = (a0x - c) D + N dax in double-double
// arithmetic with a running bound on the error, u = 2^-53 per rounding (|fl(z) - z| <=
// u |fl(z)| for normal results; underflow adds at most 2^-1075 per rounding, covered by an
// absolute allowance), and the same decision as the exact stage: x - c = R / D lies inside
// c's rounding interval when |R| plus its bound stays below the half gap times D minus its
// bound. Products use Dekker's split (exact here: every factor is at most 2^910 after the
// scaling, see nearest_crossing).

// How the calls of this thread were decided (tests and benchmarks read them).
struct Counts {
  std::uint64_t extended = 0;  // by the extended-precision filter (tried first)
  std::uint64_t filter = 0;    // by the double-double filter
  std::uint64_t exact = 0;     // by exact expansions
  std::uint64_t declined = 0;  // out of range: the caller rounds the exact rational
};
inline thread_local Counts counts;

inline constexpr double kU = 0x1p-53;
inline constexpr double kSlack = 0x1p-1060;  // per operation: underflow, far below any decision

struct DD {
  double hi = 0;
  double lo = 0;
};

// a * b; adds to `e` a bound on |ab - result| for exact a and b.
inline DD mul22(DD a, DD b, double& e) {
  const expansion::TwoTerm p = expansion::two_product_split(a.hi, b.hi);
  const double t1 = a.hi * b.lo;
  const double t2 = a.lo * b.hi;
  const double c = t1 + t2;
  const double lo = p.lo + c;
  const expansion::TwoTerm r = expansion::two_sum(p.hi, lo);
  e += std::fabs(a.lo * b.lo) * (1 + 2 * kU) + kU * (std::fabs(t1) + std::fabs(t2) + std::fabs(c) + std::fabs(lo)) +
       5 * kSlack;
  return {r.hi, r.lo};
}

// a + b; adds the bound of its roundings to `e`.
inline DD add22(DD a, DD b, double& e) {
  const expansion::TwoTerm s = expansion::two_sum(a.hi, b.hi);
  const double t = a.lo + b.lo;
  const double lo = s.lo + t;
  const expansion::TwoTerm r = expansion::two_sum(s.hi, lo);
  e += kU * (std::fabs(t) + std::fabs(lo)) + 2 * kSlack;
  return {r.hi, r.lo};
}

inline DD neg(DD a) { return {-a.hi, -a.lo}; }
inline double magnitude(DD a) { return std::fabs(a.hi) + std::fabs(a.lo); }

// u x v for exact two-term vectors, with its error bound.
inline DD cross22(DD ux, DD uy, DD vx, DD vy, double& e) {
  const DD l = mul22(ux, vy, e);
  const DD r = mul22(uy, vx, e);
  return add22(l, neg(r), e);
}

// Half the gap from c (non-zero, normal) to its neighbour above (toward +infinity) and
// below: at a power of two the gap on the side of smaller magnitude is half the other.
inline void half_gaps(double c, double& up, double& down) {
  const int e = exponent(c);
  const double h = power_of_two(e - 53);
  const bool power_of_two = (std::bit_cast<std::uint64_t>(c) & ((std::uint64_t{1} << 52) - 1)) == 0 && e >= -1022;
  const double toward_zero = power_of_two ? h / 2 : h;
  up = c > 0 ? h : toward_zero;
  down = c > 0 ? toward_zero : h;
}

// Decides the nearest double to a0 + (N / D) da for D > its bound. Returns false when the
// bounds leave it open.
inline bool filter_axis(double a0, DD da, DD d, double ed, DD n, double en, double& out, double& tail,
                        double& tail_err) {
  double c = a0 + (n.hi / d.hi) * da.hi;
  if (!std::isfinite(c)) return false;
  // D lies in [d_min, d_max]: the factors 1 -+ 4u cover the roundings of these lines.
  const double d_sum = d.hi + d.lo;
  const double d_min = d_sum * (1 - 4 * kU) - ed * (1 + 4 * kU);
  const double d_max = d_sum * (1 + 4 * kU) + ed * (1 + 4 * kU);
  if (!(d_min > 0)) return false;
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (c == 0.0 || std::fabs(c) < 0x1p-1000) return false;
    const expansion::TwoTerm off = expansion::two_diff(a0, c);  // exact
    double e = 0;
    const DD p = mul22({off.hi, off.lo}, d, e);
    e += magnitude({off.hi, off.lo}) * ed;
    const DD q = mul22(n, da, e);
    e += magnitude(da) * en;
    const DD r = add22(p, q, e);
    const double rv = r.hi + r.lo;  // within u |rv| of r
    e = (e + kU * std::fabs(rv)) * (1 + 0x1p-40) + kSlack;  // the allowance covers the bound's roundings
    double up = 0, down = 0;
    half_gaps(c, up, down);
    // x - c = R / D with D in [d_min, d_max]; the factors 1 -+ 2^-40 keep each comparison
    // right despite the rounding of its sides.
    constexpr double in = 1 - 0x1p-40, out_ = 1 + 0x1p-40;
    if (rv + e < up * d_min * in && rv - e > -down * d_min * in) {
      out = c;
      tail = rv / d_sum;
      // |R/D - rv/D~| <= (e + |rv| |D - D~| / |D~|) / d_min, plus the division's rounding;
      // grouped so that no intermediate overflows (|rv| / d_min is about the tail).
      tail_err = (e / d_min + (std::fabs(rv) / d_min) * ((ed + 4 * kU * std::fabs(d_sum)) / d_min)) * (1 + 0x1p-40) +
                 4 * kU * std::fabs(tail) + kSlack;
      return std::isfinite(tail_err);
    }
    const bool above = rv - e > up * d_max * out_;
    const bool below = rv + e < -down * d_max * out_;
    if (!above && !below) return false;  // too close to a midpoint for the bounds
    // Not c: step by the estimate of x - c (the first guess may be several ulps off when
    // a0 and t da nearly cancel), at least to the neighbour on x's side.
    const double next = c + rv / d_sum;
    c = next != c ? next : std::nextafter(c, above ? HUGE_VAL : -HUGE_VAL);
  }
  return false;
}

// ---- The extended-precision filter --------------------------------------------------------
// Before the double-double filter: the crossing in the 64-bit significand of x87's long
// double, about 11 bits beyond a double's, which decides the nearest double of all but the
// crossings within about 2^-8 of a gap from a midpoint (99.3% of star 1e4's crossings), at
// a third of the double-double filter's cost: no scaling (the long double exponent range
// holds every product and quotient of doubles below, normal: no underflow, no overflow),
// no split products, one division shared by both axes.
//
// The bound, u = 2^-64 per rounding to nearest. The differences dax = fl(a1x - a0x), ...
// carry a relative error of u each; a product of two of them 3u in all, and D~ = fl(d1 - d2)
// one u more of |d1| + |d2|: |D~ - D| <= (4u + O(u^2)) (|d1| + |d2|), taken as 5u to cover
// the O(u^2) and the rounding of the bound itself; the same for N. With D~ - eD > 0 (D's
// sign known), t = N / D and t~ = fl(N~ / D~):
//   |N~/D~ - N/D| = |N~ (D - D~) + D~ (N~ - N)| / |D~ D| <= (|N~/D~| eD + eN) / (D~ - eD),
// and |t~ - N~/D~| <= u |t~|. Then p~ = fl(t~ dax~) against P = t dax and x~ = fl(a0x + p~)
// against X = a0x + P:
//   |x~ - X| <= u |x~| + 3u |p~| + |dax~| (|t~| eD + eN) / (D~ - eD) (1 + O(u)),
// each O(u) relative slack (about 20u in all, far below 2^-50) covered by the factor
// 1 + 2^-50 on the computed bound e. c = fl(x~) is then X's nearest double when X lies
// strictly inside c's rounding interval: |x~ - c| + e below the half gap on x~'s side.
// x~ - c is exact (c is x~ rounded to fewer bits, within a factor 2 of it), and so is the
// half gap minus it (a power of two and a multiple of x~'s unit within 2^12 of each other).
// Ties are never decided here (they need e = 0). Crossings nearer zero than 2^-1020 are
// left to the later stages (near the subnormal range the half gaps stop being doubles).
// Where long double has no 64-bit significand (another ABI), or the x87 unit was set to
// round to 53 bits (some emulators do: checked once at run time), this stage declines.
inline bool extended_precision_available() {
  if constexpr (std::numeric_limits<long double>::digits < 64) {
    return false;
  } else {
    static const bool works = [] {
      volatile long double one = 1.0L, tiny = 0x1p-63L;
      const long double sum = one + tiny;
      return sum - one == tiny;
    }();
    return works;
  }
}

// One axis: the nearest double to a0 + t da, given |t~ - t| <= et (and the 3u of the
// product and the sum).
inline bool extended_axis(double a0, long double da, long double t, long double et, double& out) {
  using L = long double;
  constexpr L u = std::numeric_limits<L>::epsilon() / 2;
  const L p = t * da;
  const L x = a0 + p;
  const L e = (et * std::fabs(da) * (1 + 4 * u) + 4 * u * std::fabs(p) + u * std::fabs(x)) * (1 + 0x1p-50L);
  const double c = static_cast<double>(x);
  if (!(std::fabs(c) >= 0x1p-1020 && std::fabs(c) < HUGE_VAL)) return false;  // normal, half gaps too
  const L diff = x - c;  // exact
  double up = 0, down = 0;
  half_gaps(c, up, down);
  if (!(e < up - diff && e < down + diff)) return false;
  out = c;
  return true;
}

// The extended-precision stage of nearest_crossing: false when it leaves the crossing open.
// No tails: the area's filtered sum needs them far finer than 2^-64 of the coordinate (its
// bound adds every vertex's), which the double-double filter gives.
inline bool nearest_crossing_extended(const Point& a0, const Point& a1, const Point& b0, const Point& b1, Point& out) {
  using L = long double;
  if (!extended_precision_available()) return false;
  constexpr L u = std::numeric_limits<L>::epsilon() / 2;
  const L dax = L(a1.x) - a0.x, day = L(a1.y) - a0.y, dbx = L(b1.x) - b0.x, dby = L(b1.y) - b0.y;
  const L wx = L(b0.x) - a0.x, wy = L(b0.y) - a0.y;
  const L d1 = dax * dby, d2 = day * dbx, n1 = wx * dby, n2 = wy * dbx;
  L d = d1 - d2, n = n1 - n2;
  const L ed = (std::fabs(d1) + std::fabs(d2)) * (5 * u), en = (std::fabs(n1) + std::fabs(n2)) * (5 * u);
  if (d < 0) {
    d = -d;
    n = -n;
  }
  if (!(d - ed > 0)) return false;  // NaN and infinity land here too
  const L t = n / d;
  const L et = (en + std::fabs(t) * ed) / (d - ed) + u * std::fabs(t);
  double x = 0, y = 0;
  if (!extended_axis(a0.x, dax, t, et, x) || !extended_axis(a0.y, day, t, et, y)) return false;
  out = {x, y};
  ++counts.extended;
  return true;
}

// The stages after the extended-precision one: the double-double filter, then exact
// expansions (see nearest_crossing).
inline bool nearest_crossing_expansions(const Point& a0, const Point& a1, const Point& b0, const Point& b1, Point& out,
                                        Point* tail = nullptr, double* tail_err = nullptr) {
  const std::array<double, 8> in{a0.x, a0.y, a1.x, a1.y, b0.x, b0.y, b1.x, b1.y};
  int top = -100000;
  int unit = 100000;
  for (const double v : in) {
    if (v == 0.0) continue;
    const int e = exponent(v);
    top = std::max(top, e);
    unit = std::min(unit, e - 52);
  }
  if (top == -100000) return false;  // all zero: no proper crossing
  const int shift = kTopExponent - top;
  // Differences are multiples of 2^(unit + shift); D and N of twice that, X of three times.
  const int unit_s = unit + shift;
  if (3 * unit_s < kFloor) {
    ++counts.declined;
    return false;
  }
  std::array<double, 8> s{};
  for (std::size_t i = 0; i < 8; ++i) s[i] = times_power_of_two(in[i], shift);  // exact: stays normal
  const auto diff = [](double a, double b) { return expansion::two_diff(a, b); };
  const expansion::TwoTerm dax = diff(s[2], s[0]), day = diff(s[3], s[1]);
  const expansion::TwoTerm dbx = diff(s[6], s[4]), dby = diff(s[7], s[5]);
  const expansion::TwoTerm wx = diff(s[4], s[0]), wy = diff(s[5], s[1]);
  double cx = 0, cy = 0, tx = 0, ty = 0, ex = 0, ey = 0;
  bool decided = false;
  {  // the filter
    const auto dd = [](expansion::TwoTerm t) { return DD{t.hi, t.lo}; };
    double ed = 0, en = 0;
    DD d = cross22(dd(dax), dd(day), dd(dbx), dd(dby), ed);
    DD n = cross22(dd(wx), dd(wy), dd(dbx), dd(dby), en);
    ed = ed * (1 + 0x1p-40) + kSlack;
    en = en * (1 + 0x1p-40) + kSlack;
    if (d.hi < 0) {
      d = neg(d);
      n = neg(n);
    }
    decided = filter_axis(s[0], dd(dax), d, ed, n, en, cx, tx, ex) && filter_axis(s[1], dd(day), d, ed, n, en, cy, ty, ey);
  }
  if (decided) {
    ++counts.filter;
  } else {  // exactly
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
    if (!nearest_quotient(x_num, d, unit_d, cx, tx) || !nearest_quotient(y_num, d, unit_d, cy, ty)) {
      ++counts.declined;
      return false;
    }
    ++counts.exact;
    ex = 0x1p-40 * std::fabs(tx);
    ey = 0x1p-40 * std::fabs(ty);
  }
  // Back to the input's scale: exact, and the same rounding, unless the result falls where
  // doubles are spaced differently (the subnormal range).
  const double rx = times_power_of_two(cx, -shift);
  const double ry = times_power_of_two(cy, -shift);
  constexpr double safe = 0x1p-1020;
  if ((rx != 0.0 && std::fabs(rx) < safe) || (ry != 0.0 && std::fabs(ry) < safe)) {
    ++counts.declined;
    return false;
  }
  out = {rx, ry};
  if (tail) *tail = {times_power_of_two(tx, -shift), times_power_of_two(ty, -shift)};
  // Unscaling the tails may round them where they become subnormal.
  if (tail_err) *tail_err = times_power_of_two(std::max(ex, ey), -shift) + 0x1p-1073;
  return true;
}

}  // namespace crossing_rounding

// The nearest doubles (ties to even) to the crossing point of segments a0a1 and b0b1, which
// cross properly. Returns false when the inputs are out of this method's range (magnitudes
// more than about 2^330 apart, or a crossing point far smaller than the inputs, or one in
// the subnormal range); the caller then rounds the exact rational. With `tail`, also an
// estimate of the exact crossing minus `out` per axis, and with `tail_err` a bound on the
// estimate's error (both axes), which the area's filtered sum needs. Three stages: extended
// precision (without tails only), double-double, exact expansions, each trying only what
// the one before left open.
inline bool nearest_crossing(const Point& a0, const Point& a1, const Point& b0, const Point& b1, Point& out,
                             Point* tail = nullptr, double* tail_err = nullptr) {
  if (!tail && !tail_err && crossing_rounding::nearest_crossing_extended(a0, a1, b0, b1, out)) return true;
  return crossing_rounding::nearest_crossing_expansions(a0, a1, b0, b1, out, tail, tail_err);
}

}  // namespace mk
