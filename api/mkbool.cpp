// Runtime dispatch from kernel names to the compile-time kernels, and exact areas.
// [MK89 §3.2]
#include "api/mkbool.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "api/kernel_dispatch.hpp"
#include "api/certified_rounding.hpp"
#include "arithmetic/exact_text.hpp"

namespace mk {

namespace {

std::string point_text(const Point& p) {
  char buf[64];
  char* end = buf;
  *end++ = '(';
  end = std::to_chars(end, buf + sizeof buf, p.x == 0 ? 0.0 : p.x).ptr;
  *end++ = ' ';
  end = std::to_chars(end, buf + sizeof buf, p.y == 0 ? 0.0 : p.y).ptr;
  *end++ = ')';
  return std::string(buf, end);
}

// The core names crossing edges by ring and vertex indices; the end points make them easy to
// find in the input.
std::string crossing_message(const CrossingEdges& e, const Polygon& p) {
  const auto edge = [&](const RingEdge& x) {
    const Ring& ring = p.rings.at(static_cast<std::size_t>(x.ring));
    return "ring " + std::to_string(x.ring) + "'s edge from vertex " + std::to_string(x.from) + " " +
           point_text(ring.at(static_cast<std::size_t>(x.from))) + " to vertex " + std::to_string(x.to) + " " +
           point_text(ring.at(static_cast<std::size_t>(x.to)));
  };
  return std::string("polygon ") + (e.polygon() == 0 ? "A" : "B") + ": " + edge(e.first()) + " crosses " +
         edge(e.second()) + "; the edges of a polygon may touch but must not cross";
}

// An exact rational in another rational type of the kernels (Boost.Multiprecision's).
template <class Q>
Q rational_as(const mpq_class& v) {
  if constexpr (std::is_same_v<Q, mpq_class>) {
    return v;
  } else if constexpr (std::is_same_v<Q, boost::multiprecision::mpq_rational>) {
    return Q(v.get_mpq_t());
  } else {
    // cpp_rational: numerator and denominator through their decimal text (input only, once).
    const auto as_cpp_int = [](const mpz_class& z) { return boost::multiprecision::cpp_int(z.get_str()); };
    return Q(as_cpp_int(v.get_num()), as_cpp_int(v.get_den()));
  }
}

// The polygon with the kernel's own exact points.
template <Kernel K>
BasicPolygon<typename K::Point> kernel_polygon(const ExactPolygon& p) {
  using Q = decltype(std::declval<typename K::Point>().x);
  return map_points(p, [](const RationalPoint& v) { return typename K::Point{rational_as<Q>(v.x), rational_as<Q>(v.y)}; });
}

// P is Point (doubles) or RationalPoint (exact rationals, run by an exact kernel on its own
// number type).
template <Kernel K, class P>
BooleanOutput run(const BasicPolygon<P>& a, const BasicPolygon<P>& b, const BooleanOptions& o) {
  const Options opt{o.op, o.regular, o.sorted_ef ? EfOrganisation::sorted : EfOrganisation::hash,
                    o.all_pairs ? PairSearch::all_pairs : PairSearch::sweep, o.threads};
  if (!o.grid.empty()) (void)SnapGrid::parse(o.grid);  // std::invalid_argument before any work
  // Doubles are checked by boolean_op itself, which copies them only into a kernel point type
  // of its own (the rational kernels'); the other kernels read the input's points.
  if constexpr (!std::is_same_v<P, Point>) {
    validate_exact_coordinates(a, "A");
    validate_exact_coordinates(b, "B");
  }
  const auto t0 = std::chrono::steady_clock::now();
  BooleanResult<K> r;
  try {
    if constexpr (std::is_same_v<P, Point>) {
      r = boolean_op<K>(a, b, opt);
    } else {
      r = boolean_op<K>(kernel_polygon<K>(a), kernel_polygon<K>(b), opt);
    }
  } catch (const CrossingEdges& e) {
    const auto& p = e.polygon() == 0 ? a : b;
    if constexpr (std::is_same_v<P, Point>) {
      throw CrossingEdges(e.polygon(), e.first(), e.second(), crossing_message(e, p));
    } else {
      throw CrossingEdges(e.polygon(), e.first(), e.second(), crossing_message(e, nearest_polygon(p)));
    }
  }
  const auto t1 = std::chrono::steady_clock::now();
  return api_detail::boolean_output(r, o, std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count());
}

}  // namespace

std::vector<std::string_view> kernel_names() {
  return {ExactKernel::name,      RationalKernel::name,  RationalMpKernel::name, RationalCppKernel::name,
          AdaptiveKernel::name,   IntervalKernel::name,
#ifdef MK_WITH_CGAL
          CgalKernel::name,
#endif
          DoubleKernel::name};
}

std::string_view default_kernel() { return ExactKernel::name; }

bool is_exact_kernel(std::string_view name) {
  return name == RationalKernel::name || name == RationalMpKernel::name || name == RationalCppKernel::name ||
         name == ExactKernel::name;
}

bool is_number_type_variant(std::string_view name) {
  return name == RationalMpKernel::name || name == RationalCppKernel::name;
}

BooleanOutput compute(const Polygon& a, const Polygon& b, const BooleanOptions& options) {
  if (options.fill_rule) return api_detail::compute_with_fill_rule(a, b, options);
  return api_detail::with_kernel(options.kernel, [&]<class K>(std::type_identity<K>) { return run<K>(a, b, options); });
}

BooleanOutput compute(const ExactPolygon& a, const ExactPolygon& b, const BooleanOptions& options) {
  const auto da = as_double_polygon(a);
  const auto db = da ? as_double_polygon(b) : std::nullopt;
  if (da && db) return compute(*da, *db, options);
  if (options.fill_rule) {
    throw std::invalid_argument("fill rules read coordinates that are doubles; these polygons have coordinates that are not");
  }
  const std::string_view name = options.kernel.empty() ? default_kernel() : std::string_view(options.kernel);
  if (name == ExactKernel::name || name == RationalKernel::name) return run<RationalKernel>(a, b, options);
  if (name == RationalMpKernel::name) return run<RationalMpKernel>(a, b, options);
  if (name == RationalCppKernel::name) return run<RationalCppKernel>(a, b, options);
  if (std::find(kernel_names().begin(), kernel_names().end(), name) == kernel_names().end()) {
    return compute(Polygon{}, Polygon{}, options);  // the unknown-kernel message
  }
  throw std::invalid_argument("kernel '" + std::string(name) + "' takes doubles only; coordinates that are not doubles need an exact kernel (" +
                              std::string(ExactKernel::name) + ", " + std::string(RationalKernel::name) + ", " +
                              std::string(RationalMpKernel::name) + " or " + std::string(RationalCppKernel::name) + ")");
}

std::vector<RationalPoint> exact_vertices(const OutputIrreducible& cycle) {
  if (cycle.exact.size() != 2 * cycle.vertices.size()) {
    throw std::invalid_argument("the output has no exact coordinates (ask for BooleanOptions::exact_coordinates, exact kernels)");
  }
  std::vector<RationalPoint> out;
  out.reserve(cycle.vertices.size());
  for (std::size_t i = 0; i < cycle.vertices.size(); ++i) {
    const auto x = parse_exact_number(cycle.exact[2 * i]);
    const auto y = parse_exact_number(cycle.exact[2 * i + 1]);
    if (!x || !y) throw std::invalid_argument("the output's exact coordinate '" + cycle.exact[2 * i] + "' is not a rational");
    out.push_back({*x, *y});
  }
  return out;
}

ExactPolygon exact_result(const Output& output) {
  if (output.unbounded) {
    for (const auto& c : output.irreducible) {
      if (!c.vertices.empty() && c.vertices.size() < 3) {
        throw std::invalid_argument(
            "an unbounded result with dangling edges or isolated points has no polygon form: a hole-type polygon is "
            "the closure of its area's complement, which its two-sided and one-sided rings would not add to");
      }
    }
  }
  ExactPolygon p;
  p.type = output.unbounded ? PolygonType::hole : PolygonType::island;
  for (const auto& c : output.irreducible) {
    if (!c.vertices.empty()) p.rings.push_back(exact_vertices(c));
  }
  return p;
}

}  // namespace mk
