// The command's single-operation form: read A and B, run one Boolean operation, write the
// result as WKT, GeoJSON, native JSON or SVG. [MK89 §3.2] (procedure polygonoperation)
// [MK89 §2.3] (operations, regularity)
// Preconditions: the kernel name is one of mk::kernel_names() (checked while parsing).
#pragma once

#include <optional>
#include <string>

#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk::cli {

enum class OutputFormat { wkt, geojson, native_json, svg };

struct CommandOptions {
  Operation op = Operation::intersection;
  std::string a;  // file, `-` or inline text
  std::string b;
  std::string kernel;  // empty: mk::default_kernel()
  bool regular = true;
  std::optional<PolygonType> a_type;  // overrides the input's type when given
  std::optional<PolygonType> b_type;
  OutputFormat format = OutputFormat::wkt;
  std::string output;  // empty: standard output
  bool stats = false;
  RoundingMode rounding = RoundingMode::certified;  // see mk::BooleanOptions
  std::string grid;
};

// Runs the operation and writes its output. Throws mk::cli::UsageError (two standard
// inputs), mk::InvalidInput (bad input, named), mk::KernelFailure, mk::cli::OutputError
// (unbounded result as WKT or GeoJSON; unwritable output).
void run_command(const CommandOptions& options);

}  // namespace mk::cli
