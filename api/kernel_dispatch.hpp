// The library's runtime dispatch from a kernel name to the compile-time kernel, and the
// conversion of a kernel's result into the kernel-independent BooleanOutput (output, areas,
// statistics), shared by the binary operations and the fill-rule ones. [MK89 §3.2]
// Preconditions: `name` is one of kernel_names() (else std::invalid_argument).
#pragma once

#include <chrono>
#include <cmath>
#include <optional>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include "api/area.hpp"
#include "api/certified_rounding.hpp"
#include "api/mkbool.hpp"
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

namespace mk::api_detail {

// compute() with options.fill_rule set (api/fill.cpp).
BooleanOutput compute_with_fill_rule(const Polygon& a, const Polygon& b, const BooleanOptions& options);

// Calls f(std::type_identity<K>{}) for the kernel K named `name` (empty: the default).
template <class F>
decltype(auto) with_kernel(std::string_view name, F&& f) {
  if (name.empty()) name = default_kernel();
  if (name == ExactKernel::name) return f(std::type_identity<ExactKernel>{});
  if (name == RationalKernel::name) return f(std::type_identity<RationalKernel>{});
  if (name == RationalMpKernel::name) return f(std::type_identity<RationalMpKernel>{});
  if (name == RationalCppKernel::name) return f(std::type_identity<RationalCppKernel>{});
  if (name == AdaptiveKernel::name) return f(std::type_identity<AdaptiveKernel>{});
  if (name == IntervalKernel::name) return f(std::type_identity<IntervalKernel>{});
#ifdef MK_WITH_CGAL
  if (name == CgalKernel::name) return f(std::type_identity<CgalKernel>{});
#endif
  if (name == DoubleKernel::name) return f(std::type_identity<DoubleKernel>{});
  std::string known;
  for (const auto k : kernel_names()) known += (known.empty() ? "" : ", ") + std::string(k);
  throw std::invalid_argument("unknown kernel '" + std::string(name) + "' (built: " + known + ")");
}

// The output of a finished operation that took op_ns nanoseconds, rounded as o.rounding and
// o.grid ask (certified by default: api/certified_rounding.hpp).
template <Kernel K>
BooleanOutput boolean_output(const BooleanResult<K>& r, const BooleanOptions& o, std::int64_t op_ns) {
  std::optional<SnapGrid> grid;
  if (!o.grid.empty()) grid = SnapGrid::parse(o.grid);
  BooleanOutput out;
  out.output = to_output<K, ExactKernel>(r, o.exact_coordinates, resolve_threads(o.threads));
  const auto t2 = std::chrono::steady_clock::now();
  certify_rounding(r, out.output, o.rounding, grid);
  out.stats.rounding_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t2).count();
  out.stats.kernel = std::string(K::name);
  out.stats.op_ns = op_ns;
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

}  // namespace mk::api_detail
