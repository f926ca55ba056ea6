// The exact area of a result as a reduced rational: the shoelace terms between two input
// points summed exactly in an expansion, the terms at crossing points in homogeneous
// integer coordinates by binary splitting over their shared denominators, one gcd at the
// end. [MK89 §2.2] (islands add their area, holes subtract it) [Sh97 §2]
// Preconditions: a BooleanResult of any kernel; only cycles of 3+ vertices carry area.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <vector>

#include "arithmetic/exact_accumulator.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/boolean_op.hpp"

namespace mk {

namespace area_detail {

// Each vertex in homogeneous integer coordinates with its power of two apart:
//   x = X 2^e / D,  y = Y 2^e / D,  D > 0 odd.
// The shoelace sum over a cycle is then sum_i 2^(e_i + e_i+1) (X_i Y_i+1 - X_i+1 Y_i) /
// (D_i D_i+1), and neighbouring terms share a denominator. A range of terms l..r-1 is kept
// as P 2^E / (D_l M D_r) with M the product of the interior denominators, so that joining
// two ranges multiplies in each denominator once (binary splitting: near-linear in the size
// of the answer with GMP's fast multiplication), and the powers of two never enter the
// products: the one gcd at the end runs on odd denominators only, a fraction of the size
// they would have with the powers of two of every coordinate multiplied in.

struct Homogeneous {
  mpz_class x, y, d;  // d odd, positive
  long e = 0;
};

// The exponent of the last place of v: v is an integer multiple of 2^granularity(v).
inline int granularity(double v) { return std::ilogb(v) - 52; }

// v / 2^unit as an integer (exact when unit <= granularity(v)).
inline mpz_class scaled_integer(double v, int unit) {
  mpz_class z;
  if (v == 0.0) return z;
  const int g = granularity(v);
  mpz_set_d(z.get_mpz_t(), std::ldexp(v, -g));  // the 53-bit integer significand
  mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<mp_bitcnt_t>(g - unit));
  return z;
}

inline void lower_unit(const Point& p, int& unit) {
  if (p.x != 0.0) unit = std::min(unit, granularity(p.x));
  if (p.y != 0.0) unit = std::min(unit, granularity(p.y));
}

// Moves the common factors of two of X and Y, and all of D's, into the exponent.
inline void normalize(Homogeneous& h) {
  if (sgn(h.d) < 0) {
    h.d = -h.d;
    h.x = -h.x;
    h.y = -h.y;
  }
  const mp_bitcnt_t kd = mpz_scan1(h.d.get_mpz_t(), 0);
  if (kd > 0) {
    mpz_fdiv_q_2exp(h.d.get_mpz_t(), h.d.get_mpz_t(), kd);
    h.e -= static_cast<long>(kd);
  }
  const bool zx = sgn(h.x) == 0, zy = sgn(h.y) == 0;
  if (zx && zy) return;
  mp_bitcnt_t k = zx ? mpz_scan1(h.y.get_mpz_t(), 0) : mpz_scan1(h.x.get_mpz_t(), 0);
  if (!zy) k = std::min(k, mpz_scan1(h.y.get_mpz_t(), 0));
  if (!zx) k = std::min(k, mpz_scan1(h.x.get_mpz_t(), 0));
  if (k > 0) {
    mpz_fdiv_q_2exp(h.x.get_mpz_t(), h.x.get_mpz_t(), k);  // exact: both are multiples
    mpz_fdiv_q_2exp(h.y.get_mpz_t(), h.y.get_mpz_t(), k);
    h.e += static_cast<long>(k);
  }
}

// Homogeneous coordinates per kernel vertex type, each in the unit of its own smallest
// last place.
inline Homogeneous homogeneous(const Point& p) {
  int unit = 100000;
  lower_unit(p, unit);
  if (unit == 100000) return {0, 0, 1, 0};
  Homogeneous h{scaled_integer(p.x, unit), scaled_integer(p.y, unit), 1, unit};
  normalize(h);
  return h;
}

inline Homogeneous homogeneous(const ExactVertex& v) {
  if (!v.is_crossing) return homogeneous(v.a0);
  int unit = 100000;
  for (const Point& p : {v.a0, v.a1, v.b0, v.b1}) lower_unit(p, unit);
  const auto z = [&](double c) { return scaled_integer(c, unit); };
  const mpz_class ax = z(v.a0.x), ay = z(v.a0.y);
  const mpz_class dax = z(v.a1.x) - ax, day = z(v.a1.y) - ay;
  const mpz_class bx = z(v.b0.x), by = z(v.b0.y);
  const mpz_class dbx = z(v.b1.x) - bx, dby = z(v.b1.y) - by;
  Homogeneous h;
  h.d = dax * dby - day * dbx;
  const mpz_class n = (bx - ax) * dby - (by - ay) * dbx;  // t = n / d along a
  h.x = ax * h.d + n * dax;
  h.y = ay * h.d + n * day;
  h.e = unit;
  normalize(h);
  return h;
}

// A rational point of any number type as GMP rationals (through its exact text).
template <class Q>
RationalPoint as_mpq(const BasicRationalPoint<Q>& p) {
  if constexpr (std::is_same_v<Q, mpq_class>) {
    return p;
  } else {
    return {mpq_class(RationalNumber<Q>::text(p.x)), mpq_class(RationalNumber<Q>::text(p.y))};
  }
}

template <class Q>
Homogeneous homogeneous(const BasicRationalPoint<Q>& q) {
  const RationalPoint p = as_mpq(q);
  Homogeneous h;
  mpz_lcm(h.d.get_mpz_t(), p.x.get_den_mpz_t(), p.y.get_den_mpz_t());
  h.x = p.x.get_num() * (h.d / p.x.get_den());
  h.y = p.y.get_num() * (h.d / p.y.get_den());
  normalize(h);
  return h;
}

inline void multiply(mpz_class& r, const mpz_class& a, const mpz_class& b) {
  if (a == 1) {
    r = b;
  } else if (b == 1) {
    r = a;
  } else {
    mpz_mul(r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  }
}

// p * 2^k for k >= 0.
inline void shift_up(mpz_class& p, long k) {
  if (k > 0) mpz_mul_2exp(p.get_mpz_t(), p.get_mpz_t(), static_cast<mp_bitcnt_t>(k));
}

struct Range {
  mpz_class p;      // numerator, times 2^e
  long e = 0;
  mpz_class m = 1;  // product of the interior denominators (odd)
};

// Terms l..r-1 of an open chain of vertices v[l] .. v[r] (no wrap-around).
inline Range sum_range_open(const std::vector<Homogeneous>& v, std::size_t l, std::size_t r) {
  if (r - l == 1) {
    const Homogeneous& a = v[l];
    const Homogeneous& b = v[l + 1];
    Range out;
    out.p = a.x * b.y - b.x * a.y;
    out.e = a.e + b.e;
    return out;
  }
  const std::size_t mid = l + (r - l) / 2;
  Range left = sum_range_open(v, l, mid);
  Range right = sum_range_open(v, mid, r);
  Range out;
  out.e = std::min(left.e, right.e);
  shift_up(left.p, left.e - out.e);
  shift_up(right.p, right.e - out.e);
  mpz_class f, g;
  multiply(f, right.m, v[r].d);
  multiply(g, v[l].d, left.m);
  multiply(left.p, left.p, f);
  multiply(right.p, right.p, g);
  out.p = left.p + right.p;
  multiply(f, left.m, v[mid].d);
  multiply(out.m, f, right.m);
  return out;
}

struct Fraction {
  mpz_class p;  // times 2^e
  long e = 0;
  mpz_class q = 1;  // odd
};

// Divides p and q by their gcd (small numbers: one run of a cycle).
inline void reduce(Fraction& f) {
  if (f.q == 1) return;
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), f.p.get_mpz_t(), f.q.get_mpz_t());
  if (g != 1) {
    mpz_divexact(f.p.get_mpz_t(), f.p.get_mpz_t(), g.get_mpz_t());
    mpz_divexact(f.q.get_mpz_t(), f.q.get_mpz_t(), g.get_mpz_t());
  }
}

// An expansion's exact value as p 2^e (q = 1).
inline Fraction to_fraction(std::span<const double> e) {
  Fraction f;
  long low = 100000;
  for (const double c : e) {
    if (c != 0.0) low = std::min<long>(low, std::ilogb(c) - 52);
  }
  if (low == 100000) return f;
  f.e = low;
  for (const double c : e) {
    if (c == 0.0) continue;
    mpz_class m;
    mpz_set_d(m.get_mpz_t(), std::ldexp(c, static_cast<int>(-(std::ilogb(c) - 52))));
    shift_up(m, std::ilogb(c) - 52 - low);
    f.p += m;
  }
  return f;
}

inline Fraction sum_fractions(std::vector<Fraction>& f, std::size_t l, std::size_t r) {
  if (r == l) return {};
  if (r - l == 1) return std::move(f[l]);
  const std::size_t mid = l + (r - l) / 2;
  Fraction a = sum_fractions(f, l, mid);
  Fraction b = sum_fractions(f, mid, r);
  Fraction out;
  out.e = std::min(a.e, b.e);
  shift_up(a.p, a.e - out.e);
  shift_up(b.p, b.e - out.e);
  mpz_class s, t;
  multiply(s, a.p, b.q);
  multiply(t, b.p, a.q);
  out.p = s + t;
  multiply(out.q, a.q, b.q);
  return out;
}

// Whether vertex v is a double whose coordinates are safe factors of exact products: its
// shoelace terms with other such vertices go into the expansion.
inline bool is_safe_double(const Point& p) {
  return ExactAccumulator::is_safe_factor(p.x) && ExactAccumulator::is_safe_factor(p.y);
}
inline bool is_safe_double(const ExactVertex& v) { return !v.is_crossing && is_safe_double(v.a0); }
template <class Q>
bool is_safe_double(const BasicRationalPoint<Q>&) {
  return false;
}
inline Point as_point(const Point& p) { return p; }
inline Point as_point(const ExactVertex& v) { return v.a0; }
template <class Q>
Point as_point(const BasicRationalPoint<Q>&) {
  return {};  // never a safe double
}

// Twice the signed area of one cycle, times `sign`, split into what the expansion takes
// (terms between two safe doubles) and fractions (each maximal run of other terms, summed
// by binary splitting and reduced).
template <Kernel K>
void add_cycle(const BooleanResult<K>& r, const ResultCycle& c, double sign, ExactAccumulator& sum,
               std::vector<Fraction>& parts) {
  const std::size_t n = c.vertices.size();
  std::vector<char> safe(n);
  for (std::size_t i = 0; i < n; ++i) safe[i] = is_safe_double(r.vertex(c.vertices[i]));
  const auto term_is_safe = [&](std::size_t i) { return safe[i] && safe[(i + 1) % n]; };
  // Start at a safe term, so that runs of the other kind do not wrap around (unless every
  // term is of that kind).
  std::size_t start = 0;
  while (start < n && !term_is_safe(start)) ++start;
  const bool all_unsafe = start == n;
  if (all_unsafe) start = 0;
  std::vector<Homogeneous> run;
  std::size_t i = 0;
  while (i < n) {
    const std::size_t t = (start + i) % n;
    if (!all_unsafe && term_is_safe(t)) {
      const Point a = as_point(r.vertex(c.vertices[t]));
      const Point b = as_point(r.vertex(c.vertices[(t + 1) % n]));
      sum.add_product(sign * a.x, b.y);
      sum.add_product(-sign * b.x, a.y);
      ++i;
      continue;
    }
    // A run of terms t .. t+len-1 over vertices t .. t+len.
    std::size_t len = 0;
    while (i + len < n && (all_unsafe || !term_is_safe((start + i + len) % n))) ++len;
    run.clear();
    for (std::size_t k = 0; k <= len; ++k) run.push_back(homogeneous(r.vertex(c.vertices[(t + k) % n])));
    // sum_range reads the run as a cycle: its last vertex is the run's end, not its start.
    Range s = sum_range_open(run, 0, len);
    Fraction f;
    f.p = s.p;
    if (sign < 0) f.p = -f.p;
    f.e = s.e;
    mpz_class ends;
    multiply(ends, run.front().d, run.back().d);
    multiply(f.q, ends, s.m);
    reduce(f);
    parts.push_back(std::move(f));
    i += len;
  }
}

}  // namespace area_detail

// The exact area of the result's regular part: islands add, holes subtract. Empty when the
// result is unbounded.
template <Kernel K>
std::optional<mpq_class> exact_area(const BooleanResult<K>& r) {
  using namespace area_detail;
  if (r.unbounded) return std::nullopt;
  ExactAccumulator sum;
  std::vector<Fraction> parts;
  for (const auto& c : r.cycles) {
    if (c.vertices.size() < 3) continue;
    const double type_sign = c.type == PolygonType::island ? 1.0 : -1.0;
    if constexpr (K::is_exact) {
      // Exact kernels know each cycle's orientation exactly (its turning number), which
      // is the sign of its shoelace sum: signed sums of all cycles add up directly.
      add_cycle(r, c, type_sign * (c.counterclockwise ? 1.0 : -1.0), sum, parts);
    } else {
      // Other kernels' cycles are summed alone and their sign read off exactly.
      ExactAccumulator own;
      std::vector<Fraction> own_parts;
      add_cycle(r, c, 1.0, own, own_parts);
      own_parts.push_back(to_fraction(own.value()));
      Fraction f = sum_fractions(own_parts, 0, own_parts.size());
      if ((sgn(f.p) < 0) != (type_sign < 0)) f.p = -f.p;
      parts.push_back(std::move(f));
    }
  }
  parts.push_back(to_fraction(sum.value()));
  Fraction total = sum_fractions(parts, 0, parts.size());
  // Twice the area is p 2^e / q with q odd: the power of two needs no gcd.
  if (sgn(total.p) == 0) return mpq_class(0);
  const mp_bitcnt_t zeros = mpz_scan1(total.p.get_mpz_t(), 0);
  mpz_fdiv_q_2exp(total.p.get_mpz_t(), total.p.get_mpz_t(), zeros);
  const long e = total.e + static_cast<long>(zeros) - 1;  // and halved
  mpq_class a(total.p, total.q);
  a.canonicalize();  // an odd numerator over an odd denominator
  if (e >= 0) {
    mpq_mul_2exp(a.get_mpq_t(), a.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  } else {
    mpq_div_2exp(a.get_mpq_t(), a.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  }
  return a;
}

}  // namespace mk
