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
#include "arithmetic/shoelace.hpp"
#ifdef MK_WITH_CGAL
#include "arithmetic/kernels/cgal_kernel.hpp"
#endif
#include "core/boolean_op.hpp"
#include "core/to_output.hpp"

namespace mk {

namespace {

template <Kernel K>
BooleanOutput run(const Polygon& a, const Polygon& b, const BooleanOptions& o) {
  const Options opt{o.op, o.regular, o.sorted_ef ? EfOrganisation::sorted : EfOrganisation::hash,
                    o.all_pairs ? PairSearch::all_pairs : PairSearch::sweep};
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
    // Islands add, holes subtract: exactly from the exact coordinates where there are some.
    const auto is_island = [](const OutputIrreducible& c) { return c.type == PolygonType::island; };
    if constexpr (K::is_exact) {
      const auto exact_ring = [](const OutputIrreducible& c) {
        std::vector<RationalPoint> ring;
        ring.reserve(c.vertices.size());
        for (std::size_t i = 0; i < c.vertices.size(); ++i) {
          ring.push_back({mpq_class(c.exact[2 * i]), mpq_class(c.exact[2 * i + 1])});
        }
        return ring;
      };
      const mpq_class total = typed_area<mpq_class>(out.output.irreducible, exact_ring, is_island);
      out.stats.area_exact = total.get_str();
      out.stats.area = RationalKernel::to_nearest(total);
    } else {
      const auto rounded_ring = [](const OutputIrreducible& c) -> const std::vector<Point>& { return c.vertices; };
      out.stats.area = typed_area<double>(out.output.irreducible, rounded_ring, is_island);
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
