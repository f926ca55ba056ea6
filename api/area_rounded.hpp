// The area of a result rounded to the nearest double (ties to even) without the exact
// rational in the common case: each vertex approximated by doubles with tails and an error
// bound, the shoelace sum of the approximations summed exactly in an expansion, and the
// nearest double accepted when the sum's distance to it plus the bound stays inside half
// the gap to its neighbour; otherwise the exact area decides. [Sh97 §2] [MK89 §2.2]
// Preconditions: a BooleanResult of any kernel.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "api/area_exact.hpp"
#include "arithmetic/crossing_rounding.hpp"
#include "arithmetic/exact_accumulator.hpp"
#include "arithmetic/nearest_double.hpp"

namespace mk {

namespace area_detail {

// A vertex as doubles with tails, x = xh + xl + e_x with |e_x| <= err (and y alike).
struct Approx {
  double xh = 0, xl = 0, yh = 0, yl = 0;
  double err = 0;
  bool ok = true;
};

inline Approx approximate(const Point& p) { return {p.x, 0, p.y, 0, 0, true}; }

template <class Q>
Approx approximate(const BasicRationalPoint<Q>& q) {
  const RationalPoint p = as_mpq(q);
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

// A compensated sum with a running bound on its error [Ogita, Rump and Oishi 2005, Sum2,
// with the bound kept a posteriori instead of the worst case]: s + c approximates the sum
// of the added values, |s + c - sum| <= e. Each value is added as an exact pair hi + lo;
// two_sum moves the roundoff of s exactly into c's input, and only the two roundings of
// c's updates (at most u times their results each) enter the bound.
struct CompensatedSum {
  double s = 0;
  double c = 0;
  double e = 0;
  void add(double hi, double lo) {
    const expansion::TwoTerm t = expansion::two_sum(s, hi);
    s = t.hi;
    const double r = t.lo + lo;
    c += r;
    e += 0x1p-53 * (std::fabs(r) + std::fabs(c));
  }
  // hi + lo exactly as an expansion, and the bound.
  std::array<double, 2> value() const {
    const expansion::TwoTerm t = expansion::two_sum(c, s);
    return {t.lo, t.hi};
  }
};

// Adds s (a.x b.y - b.x a.y) of the approximations to `sum` and returns the bound on what
// it left out: the vertices' errors, the tail-by-tail products, the rounding of the
// tail products, and the underflow of Dekker's products of tiny factors (2^-1060 each
// covers it: coordinates are at most 2^450, checked by the caller).
inline double add_cross(CompensatedSum& sum, const Approx& a, const Approx& b, double s) {
  const expansion::TwoTerm p = expansion::two_product_split(s * a.xh, b.yh);
  const expansion::TwoTerm q = expansion::two_product_split(-s * b.xh, a.yh);
  sum.add(p.hi, p.lo);
  sum.add(q.hi, q.lo);
  if (a.err == 0 && b.err == 0 && a.xl == 0 && a.yl == 0 && b.xl == 0 && b.yl == 0) return 2 * 0x1p-1060;
  // The tails' products, each rounded once (u |result|).
  const double t = s * (a.xh * b.yl + a.xl * b.yh - b.xh * a.yl - b.xl * a.yh);
  sum.add(t, 0);
  const double ax = std::fabs(a.xh) + std::fabs(a.xl), ay = std::fabs(a.yh) + std::fabs(a.yl);
  const double bx = std::fabs(b.xh) + std::fabs(b.xl), by = std::fabs(b.yh) + std::fabs(b.yl);
  const double tails = std::fabs(a.xh * b.yl) + std::fabs(a.xl * b.yh) + std::fabs(b.xh * a.yl) + std::fabs(b.xl * a.yh);
  return ax * b.err + by * a.err + bx * a.err + ay * b.err + 2 * a.err * b.err + std::fabs(a.xl * b.yl) +
         std::fabs(b.xl * a.yl) + 0x1p-50 * tails + 2 * 0x1p-1060;
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

// Adds s (x_i y_i+1 - x_i+1 y_i) over one cycle's consecutive vertices to `sum` and their
// bounds to `bound`, each vertex approximated once as the walk reaches it (no array of
// approximations: on large results its allocation, page faults and copies cost more than
// the sum). False when a vertex is out of the filter's range: magnitudes beyond 2^450 could
// overflow the products, and the exact area decides.
template <Kernel K>
bool add_cycle(const BooleanResult<K>& r, const std::vector<int>& ids, double s, CompensatedSum& sum,
               double& bound) {
  const auto approx = [&r](int id, Approx& a) {
    a = approximate(r.vertex(id));
    return a.ok && std::fabs(a.xh) < 0x1p450 && std::fabs(a.yh) < 0x1p450;
  };
  Approx first, prev, cur;
  if (!approx(ids[0], first)) return false;
  prev = first;
  for (std::size_t i = 1; i < ids.size(); ++i) {
    if (!approx(ids[i], cur)) return false;
    bound += add_cross(sum, prev, cur, s);
    prev = cur;
  }
  bound += add_cross(sum, prev, first, s);
  return true;
}

}  // namespace area_detail

// The area rounded to the nearest double (ties to even; +-infinity beyond the double
// range), from the filtered sum when it decides, else from the exact area.
template <Kernel K>
std::optional<double> rounded_area(const BooleanResult<K>& r) {
  using namespace area_detail;
  if (r.unbounded) return std::nullopt;
  CompensatedSum sum;
  double bound = 0;
  bool ok = true;
  for (const auto& c : r.cycles) {
    if (c.vertices.size() < 3) continue;
    const double type_sign = c.type == PolygonType::island ? 1.0 : -1.0;
    if constexpr (K::is_exact) {
      // Exact kernels know each cycle's orientation (its turning number): the signed sums
      // of all cycles go into one sum.
      ok = add_cycle(r, c.vertices, type_sign * (c.counterclockwise ? 1.0 : -1.0), sum, bound);
    } else {
      // Other kernels' cycles are summed alone, their sign known when the sum exceeds its
      // bound (else the exact area decides).
      CompensatedSum own;
      double own_bound = 0;
      ok = add_cycle(r, c.vertices, 1.0, own, own_bound);
      own_bound = (own_bound + own.e) * (1 + 0x1p-20);
      const auto value = own.value();
      ok = ok && std::fabs(value[1]) > own_bound;
      if (!ok) break;
      const double s = type_sign * (value[1] < 0 ? -1.0 : 1.0);
      sum.add(s * value[1], s * value[0]);
      bound += own_bound;
    }
    if (!ok) break;
  }
  if (ok) {
    // The bound was summed in rounded arithmetic: a relative allowance covers that.
    const auto value = sum.value();
    if (auto d = decide_half(value, (bound + sum.e) * (1 + 0x1p-20))) return d;
  }
  return nearest_double(*exact_area(r));
}

}  // namespace mk
