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
#include "api/exact_polygon.hpp"
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
  // How Output::polygons, dangling_edges and isolated_points are rounded to doubles
  // (Output::rounding says what was done). certified (default): the nearest doubles when
  // they form a valid output, else a snap rounding onto the power-of-two grid at the scale
  // of the largest coordinate; nearest: the nearest doubles, valid or not.
  RoundingMode rounding = RoundingMode::certified;
  // Snap rounding onto multiples of this spacing, always (certified mode): a positive
  // decimal ("0.001", "1e-3") or fraction ("1/3"), taken exactly. Empty: none.
  std::string grid = {};
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
  std::int64_t rounding_ns = 0;  // certified rounding after the operation (0 when not checked)
};

struct BooleanOutput {
  Output output;
  BooleanStats stats;
};

// Throws std::invalid_argument for an unknown kernel name.
BooleanOutput compute(const Polygon& a, const Polygon& b, const BooleanOptions& options);

// The same over exact rational coordinates (for example an exact result fed back in, see
// exact_vertices). Polygons whose coordinates are all doubles go to the kernel asked for;
// others need an exact kernel over GMP rationals: the default, "exact" and "rational" all
// run the rational kernel (stats.kernel says so); other kernels throw std::invalid_argument.
BooleanOutput compute(const ExactPolygon& a, const ExactPolygon& b, const BooleanOptions& options);

// The exact vertices of a result cycle (asked for with BooleanOptions::exact_coordinates).
// Throws std::invalid_argument when the cycle has no exact coordinates.
std::vector<RationalPoint> exact_vertices(const OutputIrreducible& cycle);

// The exact result as a polygon of the paper's model, ready to be an operand: every cycle
// with at least 3 vertices as a ring (they nest by parity), type hole when unbounded.
// Throws std::invalid_argument when the output has no exact coordinates, or has dangling
// edges or isolated points (non-regular results), whose exact form is not kept.
ExactPolygon exact_result(const Output& output);

}  // namespace mk
