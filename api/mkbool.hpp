// The public library API: one call computes a Boolean operation of two polygons with a
// kernel chosen by name, and returns the kernel-independent Output.
// [MK89 §3.2] (procedure polygonoperation: inputs A, B, types, operation, regularity)
// Preconditions: none; invalid input raises mk::InvalidInput, inconsistent inexact
// arithmetic mk::KernelFailure.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk {

// Names of the kernels built into this library, fastest exact one first.
std::vector<std::string_view> kernel_names();
// The kernel used when none is named: the fastest exact kernel built.
std::string_view default_kernel();
bool is_exact_kernel(std::string_view name);
// Kernels that repeat another with a different number type (rational-mp, rational-cpp: the
// rational kernel over Boost.Multiprecision's rationals): the same results, another cost.
bool is_number_type_variant(std::string_view name);

struct BooleanOptions {
  Operation op = Operation::intersection;
  bool regular = true;
  std::string kernel;  // empty: default_kernel()
  bool sorted_ef = false;  // the paper's sorted EF table instead of the hash table
  bool all_pairs = false;  // the paper's all-pairs intersection search
  bool area = true;        // BooleanStats::area: the area rounded to the nearest double
  bool area_exact = false;  // BooleanStats::area_exact (exact kernels): costs more than the
                            // operation on results with many crossing points
  // Output::irreducible[i].exact: the exact coordinates as "p/q" strings (exact kernels).
  bool exact_coordinates = false;
};

struct BooleanStats {
  std::string kernel;
  std::int64_t op_ns = 0;  // the operation alone
  std::size_t vertices_in = 0;
  std::size_t crossings = 0;
  std::size_t vertices_out = 0;
  // Area of the result (regular part), correctly rounded to the nearest double; exact
  // kernels also give it as a reduced rational "p/q" or integer "p". Empty when unbounded
  // or not asked for (BooleanOptions::area, area_exact). An area larger than the largest
  // double (coordinates beyond about 1.3e154 can make one) is +infinity, as IEEE rounding
  // gives it, and area_beyond_double says so; area_exact still holds it exactly. Never NaN.
  std::optional<double> area;
  std::optional<std::string> area_exact;
  bool area_beyond_double = false;
};

struct BooleanOutput {
  Output output;
  BooleanStats stats;
};

// Throws std::invalid_argument for an unknown kernel name.
BooleanOutput compute(const Polygon& a, const Polygon& b, const BooleanOptions& options);

}  // namespace mk
