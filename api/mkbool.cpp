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

#include "arithmetic/kernels/double_kernel.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/filtered_kernels.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/kernels/rational_mp_kernels.hpp"
#ifdef MK_WITH_CGAL
#include "arithmetic/kernels/cgal_kernel.hpp"
#endif
#include "core/boolean_op.hpp"
#include "core/to_output.hpp"
#include "api/area.hpp"

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

template <Kernel K>
BooleanOutput run(const Polygon& a, const Polygon& b, const BooleanOptions& o) {
  const Options opt{o.op, o.regular, o.sorted_ef ? EfOrganisation::sorted : EfOrganisation::hash,
                    o.all_pairs ? PairSearch::all_pairs : PairSearch::sweep};
  validate_coordinates(a, "A");
  validate_coordinates(b, "B");
  auto ka = to_kernel_polygon<K>(a);
  auto kb = to_kernel_polygon<K>(b);
  const auto t0 = std::chrono::steady_clock::now();
  BooleanResult<K> r;
  try {
    r = boolean_op<K>(ka, kb, opt);
  } catch (const CrossingEdges& e) {
    throw CrossingEdges(e.polygon(), e.first(), e.second(), crossing_message(e, e.polygon() == 0 ? a : b));
  }
  const auto t1 = std::chrono::steady_clock::now();
  BooleanOutput out;
  out.output = to_output<K, ExactKernel>(r, o.exact_coordinates);
  out.stats.kernel = std::string(K::name);
  out.stats.op_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count();
  out.stats.vertices_in = r.stats.vertices_in;
  out.stats.crossings = r.stats.crossings;
  out.stats.vertices_out = r.stats.vertices_out;
  if (!r.unbounded) {
    if constexpr (K::is_exact) {
      if (o.area_exact) {
        const mpq_class exact = *exact_area(r);
        out.stats.area_exact = exact.get_str();
        out.stats.area = nearest_double(exact);
      }
    }
    if (o.area && !out.stats.area) out.stats.area = rounded_area(r);
    if (out.stats.area) {
      *out.stats.area += 0.0;  // never -0
      out.stats.area_beyond_double = std::isinf(*out.stats.area);
    }
  }
  return out;
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
  const std::string_view name = options.kernel.empty() ? default_kernel() : std::string_view(options.kernel);
  if (name == ExactKernel::name) return run<ExactKernel>(a, b, options);
  if (name == RationalKernel::name) return run<RationalKernel>(a, b, options);
  if (name == RationalMpKernel::name) return run<RationalMpKernel>(a, b, options);
  if (name == RationalCppKernel::name) return run<RationalCppKernel>(a, b, options);
  if (name == AdaptiveKernel::name) return run<AdaptiveKernel>(a, b, options);
  if (name == IntervalKernel::name) return run<IntervalKernel>(a, b, options);
#ifdef MK_WITH_CGAL
  if (name == CgalKernel::name) return run<CgalKernel>(a, b, options);
#endif
  if (name == DoubleKernel::name) return run<DoubleKernel>(a, b, options);
  std::string known;
  for (const auto k : kernel_names()) known += (known.empty() ? "" : ", ") + std::string(k);
  throw std::invalid_argument("unknown kernel '" + std::string(name) + "' (built: " + known + ")");
}

}  // namespace mk
