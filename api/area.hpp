// Areas of Boolean results: the double area correctly rounded by a filtered exact sum, and
// the exact area as a reduced rational by binary splitting over common denominators.
// [Sh97 §2] (expansions) [MK89 §2.2] (islands add their area, holes subtract it)
// Preconditions: a BooleanResult of any kernel; only cycles of 3+ vertices carry area. An
// unbounded result has no area (the callers check).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "arithmetic/crossing_rounding.hpp"
#include "arithmetic/expansion.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/nearest_double.hpp"
#include "core/boolean_op.hpp"

namespace mk {

namespace area_detail {

// ---- Exact area -------------------------------------------------------------------------
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

inline Homogeneous homogeneous(const RationalPoint& p) {
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

// Terms l..r-1 of the cycle `v` (term i joins vertex i and vertex i + 1 mod n).
inline Range sum_range(const std::vector<Homogeneous>& v, std::size_t l, std::size_t r) {
  const std::size_t n = v.size();
  if (r - l == 1) {
    const Homogeneous& a = v[l];
    const Homogeneous& b = v[(l + 1) % n];
    Range out;
    out.p = a.x * b.y - b.x * a.y;
    out.e = a.e + b.e;
    return out;
  }
  const std::size_t mid = l + (r - l) / 2;
  Range left = sum_range(v, l, mid);
  Range right = sum_range(v, mid, r);
  const mpz_class& dl = v[l].d;
  const mpz_class& dm = v[mid].d;
  const mpz_class& dr = v[r % n].d;
  Range out;
  out.e = std::min(left.e, right.e);
  shift_up(left.p, left.e - out.e);
  shift_up(right.p, right.e - out.e);
  mpz_class f, g;
  multiply(f, right.m, dr);
  multiply(g, dl, left.m);
  multiply(left.p, left.p, f);
  multiply(right.p, right.p, g);
  out.p = left.p + right.p;
  multiply(f, left.m, dm);
  multiply(out.m, f, right.m);
  return out;
}

struct Fraction {
  mpz_class p;  // times 2^e
  long e = 0;
  mpz_class q = 1;  // odd
};

inline Fraction sum_fractions(std::vector<Fraction>& f, std::size_t l, std::size_t r) {
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

// ---- Correctly rounded double area ------------------------------------------------------
// Each vertex approximated by doubles with tails, x = xh + xl + e_x with |e_x| <= err, and
// the shoelace sum of the approximations summed exactly in an expansion; the error bound
// collects err terms, the dropped tail-by-tail products and the underflow of two-products
// (at most 2^-1075 each). The nearest double to the area is accepted when the sum's
// distance to a candidate double, plus the bound, stays inside half the gap to its
// neighbour; otherwise the exact area decides.

struct Approx {
  double xh = 0, xl = 0, yh = 0, yl = 0;
  double err = 0;  // bound on |x - xh - xl| and on |y - yh - yl|
  bool ok = true;
};

inline Approx approximate(const Point& p) { return {p.x, 0, p.y, 0, 0, true}; }

inline Approx approximate(const RationalPoint& p) {
  Approx a;
  a.xh = nearest_double(p.x);
  a.yh = nearest_double(p.y);
  if (!std::isfinite(a.xh) || !std::isfinite(a.yh)) return {0, 0, 0, 0, 0, false};
  a.xl = nearest_double(p.x - a.xh);
  a.yl = nearest_double(p.y - a.yh);
  // Each tail is rounded once: within 2^-53 of itself, or 2^-1075 below the normal range.
  a.err = 0x1p-52 * std::max(std::fabs(a.xl), std::fabs(a.yl)) + 0x1p-1073;
  return a;
}

inline Approx approximate(const ExactVertex& v) {
  if (!v.is_crossing) return approximate(v.a0);
  Point c, tail;
  double err = 0;
  if (nearest_crossing(v.a0, v.a1, v.b0, v.b1, c, &tail, &err)) return {c.x, tail.x, c.y, tail.y, err, true};
  return approximate(ExactKernel::exact(v));
}

// A growing exact sum of doubles, compressed when it gets long.
class ExactSum {
 public:
  void add(std::span<const double> term) {
    scratch_.resize(sum_.size() + term.size() + 1);
    const std::size_t n = expansion::expansion_sum(sum_, term, scratch_);
    scratch_.resize(n);
    sum_.swap(scratch_);
    if (sum_.size() > 32) {
      const std::size_t m = expansion::compress(sum_, sum_);
      sum_.resize(m);
    }
  }
  std::span<const double> value() {
    if (sum_.empty()) sum_.push_back(0.0);
    const std::size_t m = expansion::compress(sum_, sum_);
    sum_.resize(m);
    return sum_;
  }

 private:
  std::vector<double> sum_;
  std::vector<double> scratch_;
};

// Adds +-(a.x b.y - b.x a.y) (sign `s`) to `sum` as an exact expansion of the approximations
// (the tail-by-tail products dropped) and returns the bound on what was left out.
inline double add_cross(ExactSum& sum, const Approx& a, const Approx& b, double s) {
  std::array<double, 12> parts{};
  std::size_t n = 0;
  const auto product = [&](double u, double v) {
    const expansion::TwoTerm p = expansion::two_product(s * u, v);
    parts[n++] = p.lo;
    parts[n++] = p.hi;
  };
  product(a.xh, b.yh);
  product(a.xh, b.yl);
  product(a.xl, b.yh);
  product(-b.xh, a.yh);
  product(-b.xh, a.yl);
  product(-b.xl, a.yh);
  // Each pair (lo, hi) is an expansion; grow them into one term, then into the sum.
  std::array<double, 13> term{};
  std::array<double, 13> next{};
  std::size_t len = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (parts[i] == 0.0) continue;
    len = expansion::grow_expansion(std::span<const double>(term.data(), len), parts[i], next);
    std::swap(term, next);
  }
  if (len > 0) sum.add(std::span<const double>(term.data(), len));
  const double ax = std::fabs(a.xh) + std::fabs(a.xl), ay = std::fabs(a.yh) + std::fabs(a.yl);
  const double bx = std::fabs(b.xh) + std::fabs(b.xl), by = std::fabs(b.yh) + std::fabs(b.yl);
  return ax * b.err + by * a.err + bx * a.err + ay * b.err + 2 * a.err * b.err +
         std::fabs(a.xl * b.yl) + std::fabs(b.xl * a.yl) + 6 * 0x1p-1074;
}

// Half the gap from c to its neighbour on the side of sign `toward` (+1 above, -1 below).
inline double half_gap(double c, int toward) {
  const double neighbour = std::nextafter(c, toward > 0 ? HUGE_VAL : -HUGE_VAL);
  return std::fabs(neighbour - c) / 2;  // exact: neighbours differ by a power of two
}

// The double nearest to S / 2 with |S - sum| <= bound, if the approximation decides it.
inline std::optional<double> decide_half(std::span<const double> sum, double bound) {
  const double est = expansion::estimate(sum);
  if (!std::isfinite(est) || !std::isfinite(bound)) return std::nullopt;
  const double c = est / 2;  // exact unless subnormal; any candidate works
  // T = S - 2c exactly.
  std::vector<double> t(sum.size() + 1);
  const std::size_t n = expansion::grow_expansion(sum, -2 * c, t);
  t.resize(n);
  const int ts = expansion::sign(t);
  if (ts == 0 && bound == 0) return c;
  const double t_est = std::fabs(expansion::estimate(t));
  constexpr double margin = 0x1p-40;
  // S / 2 - c = (T + (S_true - S)) / 2: within reach of c, on T's side when |T| exceeds
  // the bound (else on either side: then the smaller of the two half gaps counts; at a
  // power of two the gap below is half the gap above).
  const double reach = (t_est * (1 + margin) + bound) / 2 * (1 + margin);
  const bool side_known = ts != 0 && t_est * (1 - margin) > bound;
  const double gap = side_known ? half_gap(c, ts) : std::min(half_gap(c, 1), half_gap(c, -1));
  if (c != 0.0 && reach < gap * (1 - margin)) return c;
  return std::nullopt;
}

}  // namespace area_detail

// The exact area of the result's regular part: islands add, holes subtract. Empty when the
// result is unbounded.
template <Kernel K>
std::optional<mpq_class> exact_area(const BooleanResult<K>& r) {
  using namespace area_detail;
  if (r.unbounded) return std::nullopt;
  std::vector<Fraction> parts;
  std::vector<Homogeneous> v;
  for (const auto& c : r.cycles) {
    if (c.vertices.size() < 3) continue;
    v.clear();
    for (const int id : c.vertices) v.push_back(homogeneous(r.vertex(id)));
    Range s = sum_range(v, 0, v.size());
    // The cycle's twice-area is P 2^E / (D_0 M D_0); its magnitude counts, its type the
    // sign. Reduced here, where the numbers are small (a cycle's area has a denominator
    // dividing the product of its vertices' denominators, so this removes D_0 at least),
    // so that the sum of all cycles carries only what the answer needs into its one gcd.
    Fraction f;
    f.p = abs(s.p);
    if (c.type == PolygonType::hole) f.p = -f.p;
    f.e = s.e;
    mpz_class d0sq;
    multiply(d0sq, v[0].d, v[0].d);
    multiply(f.q, d0sq, s.m);
    if (f.q != 1) {
      mpz_class g;
      mpz_gcd(g.get_mpz_t(), f.p.get_mpz_t(), f.q.get_mpz_t());
      if (g != 1) {
        mpz_divexact(f.p.get_mpz_t(), f.p.get_mpz_t(), g.get_mpz_t());
        mpz_divexact(f.q.get_mpz_t(), f.q.get_mpz_t(), g.get_mpz_t());
      }
    }
    parts.push_back(std::move(f));
  }
  if (parts.empty()) return mpq_class(0);
  Fraction total = sum_fractions(parts, 0, parts.size());
  // Twice the area is p 2^e / q with q odd: the power of two needs no gcd.
  if (sgn(total.p) == 0) return mpq_class(0);
  const mp_bitcnt_t zeros = mpz_scan1(total.p.get_mpz_t(), 0);
  mpz_fdiv_q_2exp(total.p.get_mpz_t(), total.p.get_mpz_t(), zeros);
  const long e = total.e + static_cast<long>(zeros) - 1;  // and halved
  mpq_class a(total.p, total.q);
  a.canonicalize();  // an odd numerator over an odd denominator: the gcd is odd
  if (e >= 0) {
    mpq_mul_2exp(a.get_mpq_t(), a.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  } else {
    mpq_div_2exp(a.get_mpq_t(), a.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  }
  return a;
}

// The area rounded to the nearest double (ties to even; +-infinity beyond the double
// range), from the filtered sum when it decides, else from the exact area.
template <Kernel K>
std::optional<double> rounded_area(const BooleanResult<K>& r) {
  using namespace area_detail;
  if (r.unbounded) return std::nullopt;
  ExactSum sum;
  double bound = 0;
  bool ok = true;
  std::vector<Approx> v;
  ExactSum cycle_sum;
  for (const auto& c : r.cycles) {
    if (c.vertices.size() < 3 || !ok) continue;
    v.clear();
    for (const int id : c.vertices) {
      v.push_back(approximate(r.vertex(id)));
      const Approx& a = v.back();
      // Magnitudes beyond 2^450 could overflow the products: the exact area decides.
      if (!a.ok || !(std::fabs(a.xh) < 0x1p450) || !(std::fabs(a.yh) < 0x1p450)) ok = false;
    }
    if (!ok) break;
    // Exact kernels know each cycle's orientation (its turning number), so the signed sums
    // of all cycles go into one expansion; other kernels' cycles are summed alone and their
    // sign read off exactly (their vertices are doubles: no error).
    const double type_sign = c.type == PolygonType::island ? 1.0 : -1.0;
    if constexpr (K::is_exact) {
      const double s = type_sign * (c.counterclockwise ? 1.0 : -1.0);
      for (std::size_t i = 0; i < v.size(); ++i) bound += add_cross(sum, v[i], v[(i + 1) % v.size()], s);
    } else {
      cycle_sum = ExactSum();
      for (std::size_t i = 0; i < v.size(); ++i) bound += add_cross(cycle_sum, v[i], v[(i + 1) % v.size()], 1.0);
      const auto cv = cycle_sum.value();
      const double s = type_sign * (expansion::sign(cv) < 0 ? -1.0 : 1.0);
      std::vector<double> scaled(cv.begin(), cv.end());
      for (double& x : scaled) x *= s;
      sum.add(scaled);
    }
  }
  if (ok) {
    // The bound was summed in rounded arithmetic: a relative allowance covers that.
    if (auto d = decide_half(sum.value(), bound * (1 + 0x1p-20))) return d;
  }
  const auto exact = exact_area(r);
  return nearest_double(*exact);
}

}  // namespace mk
