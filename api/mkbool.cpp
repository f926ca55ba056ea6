// Runtime dispatch from kernel names to the compile-time kernels, and exact areas.
// [MK89 §3.2]
#include "api/mkbool.hpp"

#include <gmpxx.h>

#include <chrono>
#include <stdexcept>
#include <utility>
#include <vector>

#include "arithmetic/kernels/double_kernel.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/filtered_kernels.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#ifdef MK_WITH_CGAL
#include "arithmetic/kernels/cgal_kernel.hpp"
#endif
#include "core/boolean_op.hpp"
#include "core/to_output.hpp"

namespace mk {

namespace {

// The exact sum of many rationals, added pairwise in a balanced tree. Crossing points have
// pairwise different denominators, so the sum's denominator grows with every term: adding
// the terms one by one costs time quadratic in their number (minutes at 1e5 crossings),
// the tree costs a logarithmic number of passes of GMP's subquadratic arithmetic.
// Consumes the terms.
mpq_class sum_balanced(std::vector<mpq_class>& terms) {
  if (terms.empty()) return 0;
  for (std::size_t width = 1; width < terms.size(); width *= 2) {
    for (std::size_t i = 0; i + width < terms.size(); i += 2 * width) terms[i] += terms[i + width];
  }
  return std::move(terms[0]);
}

template <Kernel K>
BooleanOutput run(const Polygon& a, const Polygon& b, const BooleanOptions& o) {
  const Options opt{o.op, o.regular, o.sorted_ef ? EfOrganisation::sorted : EfOrganisation::hash,
                    o.all_pairs ? PairSearch::all_pairs : PairSearch::sweep, o.threads};
  validate_coordinates(a, "A");
  validate_coordinates(b, "B");
  auto ka = to_kernel_polygon<K>(a);
  auto kb = to_kernel_polygon<K>(b);
  const auto t0 = std::chrono::steady_clock::now();
  const BooleanResult<K> r = boolean_op<K>(ka, kb, opt);
  const auto t1 = std::chrono::steady_clock::now();
  BooleanOutput out;
  out.output = to_output<K, ExactKernel>(r);
  out.stats.kernel = std::string(K::name);
  out.stats.op_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count();
  out.stats.vertices_in = r.stats.vertices_in;
  out.stats.crossings = r.stats.crossings;
  out.stats.vertices_out = r.stats.vertices_out;
  if (o.area && !r.unbounded) {
    // Shoelace per area cycle, islands adding and holes subtracting.
    if constexpr (K::is_exact) {
      std::vector<mpq_class> terms;
      std::vector<mpq_class> cycle_areas;
      for (const auto& c : out.output.irreducible) {
        if (c.vertices.size() < 3) continue;
        terms.clear();
        const std::size_t n = c.vertices.size();
        for (std::size_t i = 0; i < n; ++i) {
          const std::size_t j = (i + 1) % n;
          const mpq_class xi(c.exact[2 * i]), yi(c.exact[2 * i + 1]), xj(c.exact[2 * j]), yj(c.exact[2 * j + 1]);
          terms.push_back(xi * yj - xj * yi);
        }
        mpq_class a2 = sum_balanced(terms);
        a2 = abs(a2) / 2;
        cycle_areas.push_back(c.type == PolygonType::island ? a2 : mpq_class(-a2));
      }
      const mpq_class total = sum_balanced(cycle_areas);
      out.stats.area_exact = total.get_str();
      out.stats.area = RationalKernel::to_nearest(total);
    } else {
      double total = 0;
      for (const auto& c : out.output.irreducible) {
        if (c.vertices.size() < 3) continue;
        double twice = 0;
        const std::size_t n = c.vertices.size();
        for (std::size_t i = 0; i < n; ++i) {
          const auto& p = c.vertices[i];
          const auto& q = c.vertices[(i + 1) % n];
          twice += p.x * q.y - q.x * p.y;
        }
        total += (c.type == PolygonType::island ? 0.5 : -0.5) * std::abs(twice);
      }
      out.stats.area = total;
    }
  }
  return out;
}

}  // namespace

std::vector<std::string_view> kernel_names() {
  return {ExactKernel::name, RationalKernel::name, AdaptiveKernel::name, IntervalKernel::name,
#ifdef MK_WITH_CGAL
          CgalKernel::name,
#endif
          DoubleKernel::name};
}

std::string_view default_kernel() { return ExactKernel::name; }

bool is_exact_kernel(std::string_view name) { return name == RationalKernel::name || name == ExactKernel::name; }

BooleanOutput compute(const Polygon& a, const Polygon& b, const BooleanOptions& options) {
  const std::string_view name = options.kernel.empty() ? default_kernel() : std::string_view(options.kernel);
  if (name == ExactKernel::name) return run<ExactKernel>(a, b, options);
  if (name == RationalKernel::name) return run<RationalKernel>(a, b, options);
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
