// Areas of mkbool results for the overlay benchmark: the nearest double of the exact area
// for exact kernels, the shoelace of rounded coordinates for the others.
// [MK89 §3.1 step 6] (result polygons and their types) [BRIEF §6]
// Preconditions: a regular result of boolean_op<K> (cycles of 3+ vertices carry the area;
// islands add, holes subtract). NaN for an unbounded result.
#pragma once

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/boolean_op.hpp"

namespace mk::bench {

// The area of an exact kernel's regular result, rounded to the nearest double. Not as
// mk::compute forms it (one reduced rational): over k crossing points that sum's
// denominator is the lcm of k different denominators, megabytes long at star n = 1e4,
// where mk::compute spends minutes on it. Here each shoelace term is exact (mpq) and the
// terms are added in 1024-bit floats: the sum's error, below n 2^-1000 times the sum of
// |terms|, is far below half an ulp of any area these workloads produce, so rounding the
// sum gives the nearest double of the exact area.
template <Kernel K>
double exact_area_nearest(const BooleanResult<K>& r) {
  static_assert(K::is_exact);
  if (r.unbounded) return std::numeric_limits<double>::quiet_NaN();
  constexpr mp_bitcnt_t precision = 1024;
  mpf_class total(0, precision);
  std::vector<mpq_class> xy;
  for (const ResultCycle& c : r.cycles) {
    const std::size_t n = c.vertices.size();
    if (n < 3) continue;
    xy.clear();
    for (const int v : c.vertices) {
      for (const std::string& s : K::exact_coordinates(r.vertex(v))) xy.emplace_back(s);
    }
    mpf_class twice(0, precision);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      twice += mpf_class(mpq_class(xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1]), precision);
    }
    const mpf_class area = abs(twice) / 2;
    total += c.type == PolygonType::island ? area : mpf_class(-area);
  }
  mpq_class exact;
  mpq_set_f(exact.get_mpq_t(), total.get_mpf_t());  // a binary float converts exactly
  return RationalKernel::to_nearest(exact);
}

// The area of an inexact kernel's regular result from its coordinates rounded to doubles,
// as api/mkbool.cpp computes it: islands add, holes subtract.
template <Kernel K>
double rounded_area(const BooleanResult<K>& r) {
  if (r.unbounded) return std::numeric_limits<double>::quiet_NaN();
  double total = 0;
  for (const ResultCycle& c : r.cycles) {
    if (c.vertices.size() < 3) continue;
    double twice = 0;
    for (std::size_t i = 0; i < c.vertices.size(); ++i) {
      const Point p = K::approx(r.vertex(c.vertices[i]));
      const Point q = K::approx(r.vertex(c.vertices[(i + 1) % c.vertices.size()]));
      twice += p.x * q.y - q.x * p.y;
    }
    total += (c.type == PolygonType::island ? 0.5 : -0.5) * std::abs(twice);
  }
  return total;
}

template <Kernel K>
double result_area(const BooleanResult<K>& r) {
  if constexpr (K::is_exact) {
    return exact_area_nearest(r);
  } else {
    return rounded_area(r);
  }
}

}  // namespace mk::bench
