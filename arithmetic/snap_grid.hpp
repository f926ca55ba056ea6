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

#include <array>
#include <cfenv>
#include <cmath>
#include <compare>
#include <cstdint>
#include <deque>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/interval_filter.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/nearest_double.hpp"
#include "arithmetic/rounding_guard.hpp"
#include "kernel/point.hpp"
#include "kernel/sign.hpp"

namespace mk {

// An exact point: a pair of doubles (exact == nullptr, and the box is that point), or the
// rational point *exact inside the box [x_lo, x_hi] x [y_lo, y_hi].
struct SnapPoint {
  double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
  const RationalPoint* exact = nullptr;

  static SnapPoint of(const Point& p) { return {p.x, p.x, p.y, p.y, nullptr}; }
  // A rational point kept by reference (q must outlive the SnapPoint); exact doubles
  // become a pair of doubles.
  static SnapPoint of(const RationalPoint& q) {
    const auto bounds = [](const mpq_class& v, double& lo, double& hi) {
      const double d = nearest_double(v);
      if (std::isfinite(d) && cmp(mpq_class(d), v) == 0) {
        lo = hi = d;
        return true;
      }
      lo = std::nextafter(d, -HUGE_VAL);  // the nearest double is within half an ulp
      hi = std::nextafter(d, HUGE_VAL);
      return false;
    };
    SnapPoint p;
    const bool x_exact = bounds(q.x, p.x_lo, p.x_hi);
    const bool y_exact = bounds(q.y, p.y_lo, p.y_hi);
    p.exact = x_exact && y_exact ? nullptr : &q;
    return p;
  }
  bool is_double() const { return exact == nullptr; }
  mpq_class qx() const { return exact ? exact->x : mpq_class(x_lo); }
  mpq_class qy() const { return exact ? exact->y : mpq_class(y_lo); }
  Point approx() const { return exact ? Point{nearest_double(exact->x), nearest_double(exact->y)} : Point{x_lo, y_lo}; }
};

// The predicates on snap points the sweeps need (the part of the kernel concept they use).
struct SnapPredicates {
  using Point = SnapPoint;
  static Sign compare_x(const SnapPoint& a, const SnapPoint& b) {
    if (a.x_hi < b.x_lo) return Sign::negative;
    if (b.x_hi < a.x_lo) return Sign::positive;
    if (a.is_double() && b.is_double()) return Sign::zero;
    return sign_of(cmp(a.qx(), b.qx()));
  }
  static Sign compare_y(const SnapPoint& a, const SnapPoint& b) {
    if (a.y_hi < b.y_lo) return Sign::negative;
    if (b.y_hi < a.y_lo) return Sign::positive;
    if (a.is_double() && b.is_double()) return Sign::zero;
    return sign_of(cmp(a.qy(), b.qy()));
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
    const mpq_class ax = a.qx(), ay = a.qy();
    return sign_of(sgn((b.qx() - ax) * (c.qy() - ay) - (b.qy() - ay) * (c.qx() - ax)));
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
    const auto digits = [](std::string_view d) {
      if (d.empty()) return false;
      for (const char c : d) {
        if (c < '0' || c > '9') return false;
      }
      return true;
    };
    mpq_class v;
    const std::size_t slash = text.find('/');
    if (slash != std::string_view::npos) {
      const std::string_view p = text.substr(0, slash), q = text.substr(slash + 1);
      if (!digits(p) || !digits(q) || p.size() > 4000 || q.size() > 4000) return fail();
      v = mpq_class(mpz_class(std::string(p)), mpz_class(std::string(q)));
      if (mpz_sgn(v.get_den_mpz_t()) == 0) return fail();
      v.canonicalize();
    } else {
      std::string_view mantissa = text, exponent;
      const std::size_t e = text.find_first_of("eE");
      if (e != std::string_view::npos) {
        mantissa = text.substr(0, e);
        exponent = text.substr(e + 1);
      }
      if (!exponent.empty() && exponent[0] == '+') exponent.remove_prefix(1);
      bool negative_exponent = false;
      if (!exponent.empty() && exponent[0] == '-') {
        negative_exponent = true;
        exponent.remove_prefix(1);
      }
      if (e != std::string_view::npos && (!digits(exponent) || exponent.size() > 4)) return fail();
      const std::size_t dot = mantissa.find('.');
      std::string_view whole = mantissa, fraction;
      if (dot != std::string_view::npos) {
        whole = mantissa.substr(0, dot);
        fraction = mantissa.substr(dot + 1);
      }
      if ((!whole.empty() && !digits(whole)) || (!fraction.empty() && !digits(fraction)) ||
          (whole.empty() && fraction.empty()) || mantissa.size() > 4000) {
        return fail();
      }
      long power = exponent.empty() ? 0 : std::stol(std::string(exponent));
      if (negative_exponent) power = -power;
      power -= static_cast<long>(fraction.size());
      v = mpq_class(mpz_class(std::string(whole) + std::string(fraction)));
      mpz_class ten_power;
      mpz_ui_pow_ui(ten_power.get_mpz_t(), 10, static_cast<unsigned long>(power < 0 ? -power : power));
      if (power < 0) {
        v /= ten_power;
      } else {
        v *= ten_power;
      }
    }
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
  std::optional<int> exponent() const { return exponent_; }
  bool is_power_of_two() const { return exponent_.has_value(); }
  // The spacing as text: "2^-52" for powers of two, else the reduced rational "p/q".
  std::string text() const {
    if (exponent_) return "2^" + std::to_string(*exponent_);
    return spacing_.get_str();
  }

  // The pixel index of coordinate v: floor(v / g + 1/2).
  std::int64_t index_of(double v) const {
    if (exponent_) {
      // v 2^-e is exact unless it underflows, and then it is far below 1/2 in magnitude.
      const double t = std::ldexp(v, -*exponent_);
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
    return index_of(mpq_class(v));
  }
  std::int64_t index_of(const mpq_class& v) const {
    const mpq_class t = v / spacing_ + mpq_class(1, 2);
    mpz_class f;
    mpz_fdiv_q(f.get_mpz_t(), t.get_num_mpz_t(), t.get_den_mpz_t());
    return f.get_si();
  }
  // The index of a coordinate known to lie in [lo, hi] (exact when lo == hi): the index is
  // monotone, so equal indices at both ends decide it.
  std::int64_t index_of(double lo, double hi, const mpq_class* exact) const {
    const std::int64_t a = index_of(lo);
    if (lo == hi || a == index_of(hi)) return a;
    return index_of(*exact);
  }
  Pixel pixel_of(const SnapPoint& p) const {
    return {index_of(p.x_lo, p.x_hi, p.exact ? &p.exact->x : nullptr),
            index_of(p.y_lo, p.y_hi, p.exact ? &p.exact->y : nullptr)};
  }
  // Throws std::invalid_argument when a coordinate of magnitude `largest` has a pixel index
  // beyond 2^53 (a grid far finer than the doubles there).
  void check_range(double largest) const {
    if (!(largest > 0)) return;
    if (cmp(mpq_class(largest) / spacing_, mpq_class(max_index - 1)) > 0) {
      throw std::invalid_argument("grid " + text() + " is too fine for coordinates of magnitude " +
                                  std::to_string(largest) + " (more than 2^53 grid steps)");
    }
  }

  // The coordinate k g (a centre) and (k - 1/2) g (the low boundary of index k), exact.
  mpq_class centre(std::int64_t k) const { return spacing_ * mpq_class(mpz_class(static_cast<long>(k))); }
  mpq_class boundary(std::int64_t k) const {
    mpq_class half_odd(mpz_class(2 * static_cast<long>(k) - 1), mpz_class(2));
    half_odd.canonicalize();
    return spacing_ * half_odd;
  }
  // The same as doubles when they are exactly doubles.
  std::optional<double> centre_double(std::int64_t k) const {
    if (exponent_) return std::ldexp(static_cast<double>(k), *exponent_);  // |k| <= 2^53: exact
    return exact_double(centre(k));
  }
  std::optional<double> boundary_double(std::int64_t k) const {
    if (exponent_ && *exponent_ - 1 >= -1074 && std::abs(2 * k - 1) < max_index) {
      return std::ldexp(static_cast<double>(2 * k - 1), *exponent_ - 1);
    }
    if (exponent_) return std::nullopt;
    return exact_double(boundary(k));
  }

 private:
  static std::optional<double> exact_double(const mpq_class& v) {
    const double d = nearest_double(v);
    if (std::isfinite(d) && cmp(mpq_class(d), v) == 0) return d;
    return std::nullopt;
  }
  void finish() {
    spacing_.canonicalize();
    g_ = nearest_double(spacing_);
  }
  mpq_class spacing_;
  double g_ = 0;
  std::optional<int> exponent_;
};

// Points on the grid made on demand (centres and pixel corners), kept for the lifetime of
// this store so that snap points may refer to them.
class GridPoints {
 public:
  explicit GridPoints(const SnapGrid& grid) : grid_(grid) {}
  const SnapGrid& grid() const { return grid_; }
  // The centre of pixel p.
  SnapPoint centre(const Pixel& p) { return make(grid_.centre_double(p.x), grid_.centre_double(p.y), p, false); }
  // The corner of pixel p at its low (0) or high (1) side along each axis.
  SnapPoint corner(const Pixel& p, int dx, int dy) {
    const Pixel k{p.x + dx, p.y + dy};
    return make(grid_.boundary_double(k.x), grid_.boundary_double(k.y), k, true);
  }

 private:
  SnapPoint make(std::optional<double> x, std::optional<double> y, const Pixel& k, bool boundary) {
    if (x && y) return SnapPoint::of(Point{*x, *y});
    store_.push_back({boundary ? grid_.boundary(k.x) : grid_.centre(k.x), boundary ? grid_.boundary(k.y) : grid_.centre(k.y)});
    return SnapPoint::of(store_.back());
  }
  SnapGrid grid_;
  std::deque<RationalPoint> store_;
};

// The snap geometry core/hot_pixels.hpp and core/snap_round.hpp work with: the predicates,
// a grid, and the grid points made along the way.
class SnapGeometry : public SnapPredicates {
 public:
  explicit SnapGeometry(const SnapGrid& grid) : points_(grid) {}
  const SnapGrid& grid() const { return points_.grid(); }
  Pixel pixel_of(const SnapPoint& p) const { return points_.grid().pixel_of(p); }
  SnapPoint centre(const Pixel& p) { return points_.centre(p); }
  SnapPoint corner(const Pixel& p, int dx, int dy) { return points_.corner(p, dx, dy); }
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
    return sign_of(sgn(ex * (w.qx() - u.qx()) + ey * (w.qy() - u.qy())));
  }

 private:
  GridPoints points_;
};

}  // namespace mk
