// The shoelace formula, once for the whole project: twice the signed area of a closed ring,
// and the area of a region given by typed cycles (islands add, holes subtract).
// [MK89 §3.1 step 6] (result polygons and their types) [MK89 §2.2] (FAR)
// Preconditions: a ring is a sequence of points with members x and y convertible to Number,
// its last point joined to its first; exact for Number = mpq_class, rounded for double.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace mk {

// The exact sum of many terms, added pairwise in a balanced tree. Crossing points have
// pairwise different denominators, so a rational sum's denominator grows with every term:
// adding the terms one by one costs time quadratic in their number (minutes at 1e5
// crossings), the tree a logarithmic number of passes of GMP's subquadratic arithmetic.
// For doubles the tree is also the more accurate order. Consumes the terms.
template <class Number>
Number sum_balanced(std::vector<Number>& terms) {
  if (terms.empty()) return Number(0);
  for (std::size_t width = 1; width < terms.size(); width *= 2) {
    for (std::size_t i = 0; i + width < terms.size(); i += 2 * width) terms[i] += terms[i + width];
  }
  return std::move(terms[0]);
}

// Calls add(x_i y_{i+1} - x_{i+1} y_i) for every edge i -> i+1 of the closed ring r: the
// terms whose sum is twice the signed area (positive when r runs counterclockwise). A
// caller with its own way of summing (bench/peers/mkbool_area.hpp) uses the terms alone.
template <class Number, class Ring, class Add>
void for_each_shoelace_term(const Ring& r, Add&& add) {
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = r[i];
    const auto& q = r[(i + 1) % n];
    add(Number(p.x) * Number(q.y) - Number(q.x) * Number(p.y));
  }
}

// Twice the signed area of the closed ring r.
template <class Number, class Ring>
Number twice_signed_area(const Ring& r) {
  std::vector<Number> terms;
  terms.reserve(r.size());
  for_each_shoelace_term<Number>(r, [&](Number t) { terms.push_back(std::move(t)); });
  return sum_balanced(terms);
}

// The area of a bounded region given by its cycles: each cycle of 3+ vertices adds the
// absolute value of its area when it is an island and subtracts it when it is a hole
// (dangling edges and points have none). ring_of(c) gives cycle c's points, is_island(c)
// its type.
template <class Number, class Cycles, class RingOf, class IsIsland>
Number typed_area(const Cycles& cycles, RingOf&& ring_of, IsIsland&& is_island) {
  std::vector<Number> parts;
  for (const auto& c : cycles) {
    const auto& ring = ring_of(c);
    if (ring.size() < 3) continue;
    Number twice = twice_signed_area<Number>(ring);
    if (twice < 0) twice = -twice;
    parts.push_back(is_island(c) ? Number(twice / 2) : Number(-twice / 2));
  }
  return sum_balanced(parts);
}

}  // namespace mk
