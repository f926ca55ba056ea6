// The arithmetic of snap rounding: exact points that are pairs of doubles or rationals (with
// a box of doubles that filters every predicate), a square grid whose spacing is any
// positive rational (a power of two by default), and the exact tests snap rounding asks of
// it: the pixel of a point, whether a segment meets a pixel, and the order of pixels along
// a segment. [Ho99] (hot pixels; a segment is routed through the centres of the hot pixels
// it meets) [HP02] (iterated snap rounding) [BMP06] (interval filter) [Sh97]
// Preconditions: finite coordinates; pixel indices stay within 2^53 in magnitude (checked
// by SnapGrid::check_range). Pixels are half-open: pixel (i, j) holds the points with
// (i - 1/2) g <= x < (i + 1/2) g and (j - 1/2) g <= y < (j + 1/2) g.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <array>
#include <charconv>
#include <cfenv>
#include <cmath>
#include <compare>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/exact_text.hpp"
#include "arithmetic/interval_filter.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/nearest_double.hpp"
#include "arithmetic/rounding_guard.hpp"
#include "kernel/point.hpp"
#include "kernel/sign.hpp"

namespace mk {

// A rational number made the first time it is read (most predicates are decided by the
// intervals around it).
class LazyRational {
 public:
  explicit LazyRational(mpq_class v) : value_(std::move(v)), ready_(true) {}
  explicit LazyRational(std::function<mpq_class()> make) : make_(std::move(make)) {}
  const mpq_class& get() const {
    if (!ready_) {
      value_ = make_();
      value_.canonicalize();
      ready_ = true;
      make_ = nullptr;
    }
    return value_;
  }

 private:
  mutable std::function<mpq_class()> make_;
  mutable mpq_class value_;
  mutable bool ready_ = false;
};

class SnapGrid;

// Where a coordinate's exact value comes from when its interval does not decide a predicate:
// nothing (the interval is one double, the value), a lazily made rational, or a grid point
// (half_steps times half the spacing of `grid`).
struct ExactCoordinate {
  const LazyRational* lazy = nullptr;
  const SnapGrid* grid = nullptr;
  std::int64_t half_steps = 0;
  bool is_double() const { return lazy == nullptr && grid == nullptr; }
  inline mpq_class value(double as_double) const;
};

// An exact point: each coordinate inside an interval of doubles ([x_lo, x_hi], [y_lo, y_hi]),
// which is the value itself when the coordinate is a double.
struct SnapPoint {
  double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
  ExactCoordinate qx, qy;

  static SnapPoint of(const Point& p) { return {p.x, p.x, p.y, p.y, {}, {}}; }
  // The interval around rational v: a point when v is a double.
  static bool is_double(const mpq_class& v, double& lo, double& hi) {
    const double d = nearest_double(v);
    if (std::isfinite(d) && cmp(mpq_class(d), v) == 0) {
      lo = hi = d;
      return true;
    }
    lo = std::nextafter(d, -HUGE_VAL);  // the nearest double is within half an ulp
    hi = std::nextafter(d, HUGE_VAL);
    return false;
  }
  bool is_double() const { return qx.is_double() && qy.is_double(); }
  mpq_class ex() const { return qx.value(x_lo); }
  mpq_class ey() const { return qy.value(y_lo); }
  Point approx() const {
    return {qx.is_double() ? x_lo : nearest_double(ex()), qy.is_double() ? y_lo : nearest_double(ey())};
  }
};

// Exact values kept for snap points to refer to (their addresses stay put).
class SnapPointStore {
 public:
  // The point q, exactly.
  SnapPoint add(const RationalPoint& q) {
    SnapPoint p;
    if (!SnapPoint::is_double(q.x, p.x_lo, p.x_hi)) p.qx.lazy = &values_.emplace_back(q.x);
    if (!SnapPoint::is_double(q.y, p.y_lo, p.y_hi)) p.qy.lazy = &values_.emplace_back(q.y);
    return p;
  }
  // A point known inside a box, made exactly (coordinate by coordinate) only when needed.
  SnapPoint add(double x_lo, double x_hi, double y_lo, double y_hi, std::function<mpq_class()> x,
                std::function<mpq_class()> y) {
    SnapPoint p{x_lo, x_hi, y_lo, y_hi, {}, {}};
    if (x_lo != x_hi) p.qx.lazy = &values_.emplace_back(std::move(x));
    if (y_lo != y_hi) p.qy.lazy = &values_.emplace_back(std::move(y));
    return p;
  }
  const LazyRational* add_value(std::function<mpq_class()> v) { return &values_.emplace_back(std::move(v)); }

 private:
  std::deque<LazyRational> values_;
};

// The predicates on snap points the sweeps need (the part of the kernel concept they use).
struct SnapPredicates {
  using Point = SnapPoint;
  static Sign compare_x(const SnapPoint& a, const SnapPoint& b) {
    if (a.x_hi < b.x_lo) return Sign::negative;
    if (b.x_hi < a.x_lo) return Sign::positive;
    if (a.qx.is_double() && b.qx.is_double()) return Sign::zero;  // equal doubles
    return sign_of(cmp(a.ex(), b.ex()));
  }
  static Sign compare_y(const SnapPoint& a, const SnapPoint& b) {
    if (a.y_hi < b.y_lo) return Sign::negative;
    if (b.y_hi < a.y_lo) return Sign::positive;
    if (a.qy.is_double() && b.qy.is_double()) return Sign::zero;
    return sign_of(cmp(a.ey(), b.ey()));
  }
  // Sign of (b - a) x (c - a): adaptive on doubles; an interval filter on the boxes, then
  // rationals, otherwise.
  static Sign orient2d(const SnapPoint& a, const SnapPoint& b, const SnapPoint& c) {
    if (a.is_double() && b.is_double() && c.is_double()) {
      return static_cast<Sign>(adaptive::orient2d(a.x_lo, a.y_lo, b.x_lo, b.y_lo, c.x_lo, c.y_lo));
    }
    using I = interval_filter::Interval;
    double lo = 0, hi = 0;
    {
      RoundingGuard upward(FE_UPWARD);
      const auto in = [](double l, double h) { return I(RoundingGuard::opaque(l), RoundingGuard::opaque(h)); };
      const I ax = in(a.x_lo, a.x_hi), ay = in(a.y_lo, a.y_hi);
      const I det = (in(b.x_lo, b.x_hi) - ax) * (in(c.y_lo, c.y_hi) - ay) - (in(b.y_lo, b.y_hi) - ay) * (in(c.x_lo, c.x_hi) - ax);
      volatile double l = det.lower(), h = det.upper();
      lo = l;
      hi = h;
    }
    if (lo > 0) return Sign::positive;
    if (hi < 0) return Sign::negative;
    const mpq_class ax = a.ex(), ay = a.ey();
    return sign_of(sgn((b.ex() - ax) * (c.ey() - ay) - (b.ey() - ay) * (c.ex() - ax)));
  }
};

// A pixel by its indices: the pixel (i, j) is centred on (i g, j g).
struct Pixel {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend auto operator<=>(const Pixel&, const Pixel&) = default;
};

// A square grid of spacing g > 0, exact. Pixel indices are limited to 2^53 in magnitude
// (check_range), so that they and the centres' indices are exact doubles.
class SnapGrid {
 public:
  static constexpr std::int64_t max_index = std::int64_t{1} << 53;

  // Spacing 2^e, e >= -1074 (every multiple of it that is below 2^53 2^e is a double).
  static SnapGrid power_of_two(int e) {
    SnapGrid g;
    g.exponent_ = e;
    g.spacing_ = 1;
    if (e >= 0) {
      mpz_mul_2exp(g.spacing_.get_num_mpz_t(), g.spacing_.get_num_mpz_t(), static_cast<unsigned long>(e));
    } else {
      mpz_mul_2exp(g.spacing_.get_den_mpz_t(), g.spacing_.get_den_mpz_t(), static_cast<unsigned long>(-e));
    }
    g.finish();
    return g;
  }
  // The default grid: the unit in the last place of the largest coordinate magnitude, so
  // that grid points in range are doubles and a vertex moves at most 0.71 of that ulp.
  static SnapGrid at_scale_of(double largest) {
    if (!(largest > 0)) return power_of_two(-1074);
    return power_of_two(std::max(std::ilogb(largest) - 52, -1074));
  }
  // A positive decimal ("0.001", "1e-3", "25") or rational ("1/3"), taken as the exact
  // number it writes. Throws std::invalid_argument otherwise.
  static SnapGrid parse(std::string_view text) {
    const auto fail = [&]() -> SnapGrid {
      throw std::invalid_argument("grid '" + std::string(text) +
                                  "' is not a positive decimal number (like 0.001, 1e-3 or 25) or a fraction p/q");
    };
    // Decimal digits only (GMP's own parser reads a leading 0 as octal).
    const std::optional<mpq_class> parsed = parse_exact_number(text, 4000, 4000);
    if (!parsed) return fail();
    const mpq_class& v = *parsed;
    if (sgn(v) <= 0) return fail();
    SnapGrid g;
    g.spacing_ = v;
    g.finish();
    // A power of two is recognised, so that its grid points are doubles.
    const mpz_class& num = g.spacing_.get_num();
    const mpz_class& den = g.spacing_.get_den();
    if (mpz_popcount(num.get_mpz_t()) == 1 && mpz_popcount(den.get_mpz_t()) == 1) {
      const long e2 = static_cast<long>(mpz_scan1(num.get_mpz_t(), 0)) - static_cast<long>(mpz_scan1(den.get_mpz_t(), 0));
      if (e2 >= -1074 && e2 <= 1023) g.exponent_ = static_cast<int>(e2);
    }
    if (!std::isfinite(g.g_) || g.g_ == 0) {
      throw std::invalid_argument("grid '" + std::string(text) + "' is outside the range of doubles");
    }
    return g;
  }

  const mpq_class& spacing() const { return spacing_; }
  double spacing_lo() const { return g_lo_; }
  double spacing_hi() const { return g_hi_; }
  std::optional<int> exponent() const { return exponent_; }
  bool is_power_of_two() const { return exponent_.has_value(); }
  // The spacing as text: "2^-52" for powers of two, else the reduced rational "p/q".
  std::string text() const {
    if (exponent_) return "2^" + std::to_string(*exponent_);
    return spacing_.get_str();
  }
  // The same for a message: a spacing whose exact text is long (1e-300 is a 1 over 301
  // digits) as "about" its value to four digits, rounded by MPFR.
  std::string readable_text() const {
    std::string t = text();
    if (t.size() <= 32) return t;
    mpfr_t v;
    mpfr_init2(v, 64);
    mpfr_set_q(v, spacing_.get_mpq_t(), MPFR_RNDN);
    char* printed = nullptr;
    const int n = mpfr_asprintf(&printed, "%.4Rg", v);
    mpfr_clear(v);
    if (n < 0) return t;
    t = std::string("about ") + printed;
    mpfr_free_str(printed);
    return t;
  }

  // The pixel index of coordinate v: floor(v / g + 1/2). Throws std::range_error when it is
  // beyond 2^62 in magnitude.
  std::int64_t index_of(double v) const {
    const std::optional<std::int64_t> k = index_in_range(v);
    if (!k) throw std::range_error("snap rounding: a coordinate beyond the grid's index range");
    return *k;
  }
  // The same, or nothing when the index is beyond 2^62 in magnitude (a bound of an interval
  // box may be, when the coordinate it bounds is not).
  std::optional<std::int64_t> index_in_range(double v) const {
    if (exponent_) {
      // v 2^-e is exact unless it underflows, and then it is far below 1/2 in magnitude.
      const double t = std::ldexp(v, -*exponent_);
      if (!(std::fabs(t) < 0x1p62)) return std::nullopt;
      if (std::fabs(t) >= 0x1p52) return static_cast<std::int64_t>(t);  // an integer already
      const double f = std::floor(t);
      return static_cast<std::int64_t>(t >= f + 0.5 ? f + 1 : f);  // f + 0.5 is exact here
    }
    // Filter: t = v / g_ is within 2^-51 |t| of v / g (g_ is g rounded, then one division),
    // and s = t + 1/2 and s - floor(s) add an error below 2^-52 (|s| + 1); the index is
    // floor(s) unless s lies that close to an integer.
    const double t = v / g_;
    if (std::isfinite(t) && std::fabs(t) < 0x1p50) {
      const double s = t + 0.5;
      const double f = std::floor(s);
      const double d = s - f;
      const double e = (std::fabs(t) + std::fabs(s) + 2) * 0x1p-49;
      if (d > e && d < 1 - e) return static_cast<std::int64_t>(f);
    }
    if (!std::isfinite(v)) return std::nullopt;
    return index_in_range(mpq_class(v));
  }
  std::optional<std::int64_t> index_in_range(const mpq_class& v) const {
    const mpq_class t = v / spacing_ + mpq_class(1, 2);
    mpz_class f;
    mpz_fdiv_q(f.get_mpz_t(), t.get_num_mpz_t(), t.get_den_mpz_t());
    if (mpz_sizeinbase(f.get_mpz_t(), 2) > 62) return std::nullopt;
    return f.get_si();
  }
  std::int64_t index_of(const mpq_class& v) const {
    const std::optional<std::int64_t> k = index_in_range(v);
    if (!k) throw std::range_error("snap rounding: a coordinate beyond the grid's index range");
    return *k;
  }
  // The index of a coordinate known to lie in [lo, hi] (exact when lo == hi): the index is
  // monotone, so equal indices at both ends decide it. A bound whose index is out of range
  // decides nothing (the box of a crossing can be far wider than the grid's range).
  std::int64_t index_of(double lo, double hi, const ExactCoordinate& exact) const {
    if (lo == hi) return index_of(lo);
    const std::optional<std::int64_t> a = index_in_range(lo);
    if (a && a == index_in_range(hi)) return *a;
    return index_of(exact.value(lo));
  }
  Pixel pixel_of(const SnapPoint& p) const { return {index_of(p.x_lo, p.x_hi, p.qx), index_of(p.y_lo, p.y_hi, p.qy)}; }
  // Throws std::invalid_argument when a coordinate of magnitude `largest` has a pixel index
  // beyond 2^53 (a grid far finer than the doubles there).
  void check_range(double largest) const {
    if (!(largest > 0)) return;
    if (cmp(mpq_class(largest) / spacing_, mpq_class(max_index - 1)) > 0) {
      char magnitude[32];
      const auto end = std::to_chars(magnitude, magnitude + sizeof magnitude, largest).ptr;
      throw std::invalid_argument("grid " + readable_text() + " is too fine for coordinates of magnitude " +
                                  std::string(magnitude, end) + " (more than 2^53 grid steps)");
    }
  }

  // The coordinate k g (a centre) and (k - 1/2) g (the low boundary of index k), exact.
  mpq_class centre(std::int64_t k) const { return spacing_ * mpq_class(mpz_class(static_cast<long>(k))); }
  mpq_class boundary(std::int64_t k) const {
    mpq_class half_odd(mpz_class(2 * static_cast<long>(k) - 1), mpz_class(2));
    half_odd.canonicalize();
    return spacing_ * half_odd;
  }
  // The same as doubles when they are exactly doubles (for spacings that are not powers of
  // two, found only when the spacing's numerator and denominator are small).
  std::optional<double> centre_double(std::int64_t k) const {
    if (exponent_) return std::ldexp(static_cast<double>(k), *exponent_);  // |k| <= 2^53: exact
    double d = 0;
    return quotient(k, 1, d) ? std::optional<double>(d) : std::nullopt;
  }
  std::optional<double> boundary_double(std::int64_t k) const {
    if (exponent_ && *exponent_ - 1 >= -1074 && std::abs(2 * k - 1) < max_index) {
      return std::ldexp(static_cast<double>(2 * k - 1), *exponent_ - 1);
    }
    if (exponent_) return std::nullopt;
    double d = 0;
    return quotient(2 * k - 1, 2, d) ? std::optional<double>(d) : std::nullopt;
  }
  // The exact value of h g / 2.
  mpq_class half_steps(std::int64_t h) const {
    mpq_class v(mpz_class(static_cast<long>(h)), mpz_class(2));
    v.canonicalize();
    return spacing_ * v;
  }
  // An interval [lo, hi] of doubles holding h g / 2; true when it is that value exactly.
  bool half_steps_interval(std::int64_t h, double& lo, double& hi) const {
    const double hd = static_cast<double>(h);  // exact below 2^53, else within half an ulp
    const bool h_exact = std::llabs(h) <= max_index;
    if (exponent_ && h_exact && *exponent_ - 1 >= -1074) {
      lo = hi = std::ldexp(hd, *exponent_ - 1);
      return true;
    }
    if (small_ && h_exact && std::fabs(hd * p_) < 0x1p53 && 2 * q_ < 0x1p53) {
      const double num = hd * p_, den = 2 * q_;
      const double d = num / den;  // correctly rounded
      if (std::fma(-d, den, num) == 0) {
        lo = hi = d;
        return true;
      }
      lo = std::nextafter(d, -HUGE_VAL);
      hi = std::nextafter(d, HUGE_VAL);
      return false;
    }
    using I = interval_filter::Interval;
    RoundingGuard upward(FE_UPWARD);
    const auto in = [](double l, double u) { return I(RoundingGuard::opaque(l), RoundingGuard::opaque(u)); };
    const I v = in(std::nextafter(hd, -HUGE_VAL), std::nextafter(hd, HUGE_VAL)) * in(g_lo_, g_hi_) / in(2, 2);
    volatile double l = v.lower(), u = v.upper();
    lo = l;
    hi = u;
    return false;
  }
  // The nearest double to k g (the written coordinate of a centre).
  double nearest_centre(std::int64_t k) const {
    if (const auto d = centre_double(k)) return *d;
    double d = 0;
    if (small_ && std::fabs(static_cast<double>(k) * p_) < 0x1p53) {
      quotient(k, 1, d);  // IEEE division of exact doubles: correctly rounded
      return d;
    }
    return nearest_double(centre(k));
  }

 private:
  // n p / (m q) rounded to nearest, for a spacing p / q with both exact doubles and |n p|
  // below 2^53: true when that quotient is exact (the remainder of a correctly rounded
  // division is a double, so one fma finds it).
  bool quotient(std::int64_t n, int m, double& d) const {
    if (!small_) return false;
    const double num = static_cast<double>(n) * p_;  // exact below 2^53
    const double den = m * q_;
    if (!(std::fabs(num) < 0x1p53) || !(den < 0x1p53)) return false;
    d = num / den;
    return std::fma(-d, den, num) == 0;
  }
  void finish() {
    spacing_.canonicalize();
    g_ = nearest_double(spacing_);
    g_lo_ = std::nextafter(g_, 0.0);
    g_hi_ = std::nextafter(g_, HUGE_VAL);
    const mpz_class& num = spacing_.get_num();
    const mpz_class& den = spacing_.get_den();
    small_ = mpz_sizeinbase(num.get_mpz_t(), 2) <= 52 && mpz_sizeinbase(den.get_mpz_t(), 2) <= 52;
    if (small_) {
      p_ = num.get_d();
      q_ = den.get_d();
    }
  }
  mpq_class spacing_;
  double g_ = 0, g_lo_ = 0, g_hi_ = 0;  // the spacing rounded to nearest, and a box around it
  bool small_ = false;                   // numerator p_ and denominator q_ are exact doubles
  double p_ = 0, q_ = 0;
  std::optional<int> exponent_;
};

// Grid points as snap points: coordinates k g (centres) and (k - 1/2) g (boundaries), each
// a double when it is one, else an interval with the grid to make it exactly.
class GridPoints {
 public:
  explicit GridPoints(const SnapGrid& grid) : grid_(grid) {}
  const SnapGrid& grid() const { return grid_; }
  // The centre of pixel p.
  SnapPoint centre(const Pixel& p) const { return point(coordinate(2 * p.x), coordinate(2 * p.y)); }
  // The corner of pixel p at its low (0) or high (1) side along each axis.
  SnapPoint corner(const Pixel& p, int dx, int dy) const {
    return point(coordinate(2 * (p.x + dx) - 1), coordinate(2 * (p.y + dy) - 1));
  }

 private:
  struct Coordinate {
    double lo, hi;
    ExactCoordinate exact;
  };
  static SnapPoint point(const Coordinate& x, const Coordinate& y) { return {x.lo, x.hi, y.lo, y.hi, x.exact, y.exact}; }
  Coordinate coordinate(std::int64_t half_steps) const {
    Coordinate c{0, 0, {}};
    if (grid_.half_steps_interval(half_steps, c.lo, c.hi)) return c;
    c.exact.grid = &grid_;
    c.exact.half_steps = half_steps;
    return c;
  }
  const SnapGrid& grid_;
};

// The snap geometry core/hot_pixels.hpp and core/snap_round.hpp work with: the predicates,
// a grid, and the grid points made along the way.
class SnapGeometry : public SnapPredicates {
 public:
  explicit SnapGeometry(const SnapGrid& grid) : grid_(grid), points_(grid_) {}
  SnapGeometry(const SnapGeometry&) = delete;  // points_ refers to grid_
  SnapGeometry& operator=(const SnapGeometry&) = delete;
  const SnapGrid& grid() const { return grid_; }
  Pixel pixel_of(const SnapPoint& p) const { return points_.grid().pixel_of(p); }
  SnapPoint centre(const Pixel& p) const { return points_.centre(p); }
  SnapPoint corner(const Pixel& p, int dx, int dy) const { return points_.corner(p, dx, dy); }
  // The order of the centres of pixels p and q along the direction from u to w: the sign of
  // (centre(p) - centre(q)) . (w - u), in units of the spacing.
  static Sign compare_along(const SnapPoint& u, const SnapPoint& w, const Pixel& p, const Pixel& q) {
    const auto exact_int = [](std::int64_t v) { return std::llabs(v) <= SnapGrid::max_index; };
    const std::int64_t dx = p.x - q.x, dy = p.y - q.y;
    if (exact_int(dx) && exact_int(dy)) {
      using I = interval_filter::Interval;
      double lo = 0, hi = 0;
      {
        RoundingGuard upward(FE_UPWARD);
        const auto in = [](double l, double h) { return I(RoundingGuard::opaque(l), RoundingGuard::opaque(h)); };
        const I ex = in(static_cast<double>(dx), static_cast<double>(dx));
        const I ey = in(static_cast<double>(dy), static_cast<double>(dy));
        const I d = ex * (in(w.x_lo, w.x_hi) - in(u.x_lo, u.x_hi)) + ey * (in(w.y_lo, w.y_hi) - in(u.y_lo, u.y_hi));
        volatile double l = d.lower(), h = d.upper();
        lo = l;
        hi = h;
      }
      if (lo > 0) return Sign::positive;
      if (hi < 0) return Sign::negative;
    }
    const mpq_class ex(mpz_class(static_cast<long>(dx))), ey(mpz_class(static_cast<long>(dy)));
    return sign_of(sgn(ex * (w.ex() - u.ex()) + ey * (w.ey() - u.ey())));
  }

 private:
  SnapGrid grid_;
  GridPoints points_;
};

inline mpq_class ExactCoordinate::value(double as_double) const {
  if (lazy) return lazy->get();
  if (grid) return grid->half_steps(half_steps);
  return mpq_class(as_double);
}

}  // namespace mk
