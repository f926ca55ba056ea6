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

struct BooleanOptions {
  Operation op = Operation::intersection;
  bool regular = true;
  std::string kernel;  // empty: default_kernel()
  bool sorted_ef = false;  // the paper's sorted EF table instead of the hash table
  bool all_pairs = false;  // the paper's all-pairs intersection search
  bool area = true;        // compute BooleanStats::area and area_exact
  // Threads for the phases that run in parallel (candidate pairs, crossings, classification,
  // the two polygons' preparation); 0: every core. Results are the same, bit for bit, on
  // any number of threads.
  unsigned threads = 0;
};

struct BooleanStats {
  std::string kernel;
  std::int64_t op_ns = 0;  // the operation alone
  std::size_t vertices_in = 0;
  std::size_t crossings = 0;
  std::size_t vertices_out = 0;
  // Area of the result (regular part), rounded; exact kernels also give it as a reduced
  // rational "p/q" or integer "p". Empty when unbounded or not asked for
  // (BooleanOptions::area).
  std::optional<double> area;
  std::optional<std::string> area_exact;
};

struct BooleanOutput {
  Output output;
  BooleanStats stats;
};

// Throws std::invalid_argument for an unknown kernel name.
BooleanOutput compute(const Polygon& a, const Polygon& b, const BooleanOptions& options);

}  // namespace mk
