// Fill rules, N-ary union and intersection, and make-valid in the library: rings into one
// winding arrangement per call, the result predicate over their winding numbers.
// [MK89 §3.1] paper-notes.md, deviation "winding numbers" [BRIEF §1]
// Preconditions: none; invalid input raises mk::InvalidInput, bad options
// std::invalid_argument.
#include <gmpxx.h>

#include <algorithm>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/kernel_dispatch.hpp"
#include "core/fill_op.hpp"

namespace mk {

namespace {

// The sign of a ring's signed area: a double shoelace sum with an error bound (rounding of
// each product and of the n-term sum, plus underflow), the exact rational sum when the
// bound does not decide it.
int signed_area_sign(const Ring& r) {
  const std::size_t n = r.size();
  double sum = 0;
  double magnitude = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = r[i];
    const Point& q = r[(i + 1) % n];
    const double a = p.x * q.y;
    const double b = q.x * p.y;
    sum += a - b;
    magnitude += std::abs(a) + std::abs(b);
  }
  const double bound = (static_cast<double>(n) + 4) * DBL_EPSILON * magnitude + static_cast<double>(4 * n + 4) * DBL_TRUE_MIN;
  if (std::isfinite(sum) && std::isfinite(bound) && std::abs(sum) > bound) return sum > 0 ? 1 : -1;
  mpq_class exact = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = r[i];
    const Point& q = r[(i + 1) % n];
    exact += mpq_class(p.x) * mpq_class(q.y) - mpq_class(q.x) * mpq_class(p.y);
  }
  return sgn(exact);
}

Ring oriented(const Ring& r, bool counterclockwise) {
  const int s = signed_area_sign(r);
  if (s == 0 || (s > 0) == counterclockwise) return r;
  return Ring(r.rbegin(), r.rend());
}

// The rings of several inputs, each ring's input in `group`.
struct GroupedRings {
  std::vector<Ring> rings;
  std::vector<int> group;
  int groups = 0;
};

void add_group(GroupedRings& g, const Polygon& p) {
  for (const Ring& r : p.rings) {
    g.rings.push_back(r);
    g.group.push_back(g.groups);
  }
  ++g.groups;
}

// The faces around a point as fill_op lists them (one winding number per group each).
using Faces = std::vector<const int*>;

template <Kernel K, class InResult, class InClosed>
BooleanOutput run_fill(const GroupedRings& in, const BooleanOptions& o, InResult&& in_result, const InClosed& in_closed) {
  std::vector<BasicRing<typename K::Point>> rings;
  rings.reserve(in.rings.size());
  for (const Ring& r : in.rings) {
    auto& kr = rings.emplace_back();
    kr.reserve(r.size());
    for (const Point& q : r) kr.push_back(K::point(q));
  }
  const auto t0 = std::chrono::steady_clock::now();
  BooleanResult<K> r = fill_op<K>(
      build_winding_arrangement<K>(rings, in.group, in.groups, o.all_pairs ? PairSearch::all_pairs : PairSearch::sweep),
      in_result, o.regular ? nullptr : &in_closed);
  const auto t1 = std::chrono::steady_clock::now();
  return api_detail::boolean_output(r, o, std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count());
}

// in_result(w): whether a face (w: its winding number per group) is in the result;
// in_closed(faces): whether the closed-set result holds a point whose neighbourhood meets
// those faces (asked in non-regular mode only).
template <class InResult, class InClosed>
BooleanOutput dispatch_fill(const GroupedRings& in, const BooleanOptions& o, InResult&& in_result, InClosed&& in_closed) {
  for (std::size_t r = 0; r < in.rings.size(); ++r) {
    Polygon one;
    one.rings.push_back(in.rings[r]);
    validate_coordinates(one, "input");
  }
  return api_detail::with_kernel(o.kernel, [&]<class K>(std::type_identity<K>) { return run_fill<K>(in, o, in_result, in_closed); });
}

// One group read by `rule` (union-all, make-valid): a face is in the result when filled, a
// point in the closed result when a face around it is.
BooleanOutput dispatch_one_region(const GroupedRings& in, const BooleanOptions& o, FillRule rule) {
  const auto filled = [=](const int* w) { return is_filled(rule, w[0]); };
  return dispatch_fill(in, o, filled, [=](const Faces& faces) { return std::any_of(faces.begin(), faces.end(), filled); });
}

GroupedRings rings_of_parts(const MultiPolygon& parts, FillRule rule, bool one_group) {
  GroupedRings g;
  for (const OgcPolygon& part : parts) {
    MultiPolygon one{part};
    add_group(g, fill_rule_polygon(one, rule));
  }
  if (one_group) {
    std::fill(g.group.begin(), g.group.end(), 0);
    g.groups = 1;
  }
  return g;
}

}  // namespace

Polygon fill_rule_polygon(const MultiPolygon& mp, FillRule rule) {
  Polygon p = to_polygon(mp);
  if (rule != FillRule::union_) return p;
  validate_coordinates(p, "input");  // before the areas' signs are taken
  std::size_t r = 0;
  for (const OgcPolygon& part : mp) {
    p.rings[r] = oriented(part.shell, true);
    ++r;
    for (const Ring& h : part.holes) p.rings[r++] = oriented(h, false);
  }
  return p;
}

namespace api_detail {

BooleanOutput compute_with_fill_rule(const Polygon& a, const Polygon& b, const BooleanOptions& o) {
  GroupedRings in;
  add_group(in, a);
  add_group(in, b);
  const FillRule rule = *o.fill_rule;
  const bool hole_a = a.type == PolygonType::hole;
  const bool hole_b = b.type == PolygonType::hole;
  const Operation op = o.op;
  const auto in_region = [=](int g, int w) { return is_filled(rule, w) != (g == 0 ? hole_a : hole_b); };
  return dispatch_fill(
      in, o, [=](const int* w) { return is_face_in_result(op, in_region(0, w[0]), in_region(1, w[1])); },
      [=](const Faces& faces) {
        // Each input's closure holds the point when a face around it is in the input's
        // region, its interior when every one is.
        bool closure[2] = {false, false}, interior[2] = {true, true};
        for (const int* w : faces) {
          for (int g = 0; g < 2; ++g) {
            const bool in = in_region(g, w[g]);
            closure[g] = closure[g] || in;
            interior[g] = interior[g] && in;
          }
        }
        return is_in_closed_result(op, closure[0], interior[0], closure[1], interior[1]);
      });
}

}  // namespace api_detail

BooleanOutput union_all(const MultiPolygon& parts, const BooleanOptions& o) {
  const FillRule rule = o.fill_rule.value_or(FillRule::union_);
  return dispatch_one_region(rings_of_parts(parts, rule, true), o, rule);
}

BooleanOutput intersection_all(const MultiPolygon& parts, const BooleanOptions& o) {
  if (parts.empty()) throw InvalidInput("intersection-all of no polygons: the plane, which has no bounded form");
  const FillRule rule = o.fill_rule.value_or(FillRule::union_);
  const GroupedRings in = rings_of_parts(parts, rule, false);
  const int n = in.groups;
  return dispatch_fill(
      in, o,
      [=](const int* w) {
        for (int g = 0; g < n; ++g) {
          if (!is_filled(rule, w[g])) return false;
        }
        return true;
      },
      [=](const Faces& faces) {  // in every part's closure
        for (int g = 0; g < n; ++g) {
          if (std::none_of(faces.begin(), faces.end(), [&](const int* w) { return is_filled(rule, w[g]); })) return false;
        }
        return true;
      });
}

BooleanOutput make_valid(const MultiPolygon& input, const BooleanOptions& o) {
  const FillRule rule = o.fill_rule.value_or(FillRule::evenodd);
  GroupedRings in;
  add_group(in, fill_rule_polygon(input, rule));
  return dispatch_one_region(in, o, rule);
}

}  // namespace mk
