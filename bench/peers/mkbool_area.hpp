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
#include "arithmetic/shoelace.hpp"
#include "core/boolean_op.hpp"

namespace mk::bench {

// The area of an exact kernel's regular result, rounded to the nearest double. Not as
// mk::compute forms it (one reduced rational): over k crossing points that sum's
// denominator is the lcm of k different denominators, megabytes long at star n = 1e4,
// where mk::compute spends seconds on it. Here each shoelace term (arithmetic/shoelace.hpp)
// is exact (mpq) and the terms are added in 1024-bit floats: the sum's error, below
// n 2^-1000 times the sum of |terms|, is far below half an ulp of any area these workloads
// produce, so rounding the sum gives the nearest double of the exact area.
template <Kernel K>
double exact_area_nearest(const BooleanResult<K>& r) {
  static_assert(K::is_exact);
  if (r.unbounded) return std::numeric_limits<double>::quiet_NaN();
  constexpr mp_bitcnt_t precision = 1024;
  mpf_class total(0, precision);
  std::vector<RationalPoint> ring;
  for (const ResultCycle& c : r.cycles) {
    if (c.vertices.size() < 3) continue;
    ring.clear();
    for (const int v : c.vertices) {
      const auto xy = K::exact_coordinates(r.vertex(v));
      ring.push_back({mpq_class(xy[0]), mpq_class(xy[1])});
    }
    mpf_class twice(0, precision);
    for_each_shoelace_term<mpq_class>(ring, [&](const mpq_class& t) { twice += mpf_class(t, precision); });
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
  const auto ring = [&](const ResultCycle& c) {
    std::vector<Point> out;
    for (const int v : c.vertices) out.push_back(K::approx(r.vertex(v)));
    return out;
  };
  return typed_area<double>(r.cycles, ring, [](const ResultCycle& c) { return c.type == PolygonType::island; });
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
