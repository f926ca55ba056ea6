// The command's single-operation form: read A and B, run one Boolean operation, write the
// result as WKT, GeoJSON, native JSON or SVG. [MK89 §3.2] (procedure polygonoperation)
// [MK89 §2.3] (operations, regularity)
// Preconditions: the kernel name is one of mk::kernel_names() (checked while parsing).
#pragma once

#include <optional>
#include <string>

#include "api/mkbool.hpp"
#include "core/fill_rule.hpp"
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
  // Reads A and B by a fill rule (any rings: crossing, overlapping); regular output only.
  std::optional<FillRule> fill_rule;
  unsigned threads = 0;  // 0: every core
  RoundingMode rounding = RoundingMode::certified;  // see mk::BooleanOptions
  std::string grid;
};

// Runs the operation and writes its output. Throws mk::cli::UsageError (two standard
// inputs), mk::InvalidInput (bad input, named), mk::KernelFailure, mk::cli::OutputError
// (unbounded result as WKT or GeoJSON; unwritable output).
void run_command(const CommandOptions& options);

// The operations on the parts of one input (api: union_all, intersection_all, make_valid).
enum class PartsOperation { union_all, intersection_all, make_valid };

struct PartsCommandOptions {
  PartsOperation op = PartsOperation::union_all;
  std::string input;  // file, `-` or inline text
  std::string kernel;
  std::optional<FillRule> fill_rule;  // empty: the operation's default (union, or evenodd)
  bool regular = true;
  OutputFormat format = OutputFormat::wkt;
  std::string output;
  bool stats = false;
  RoundingMode rounding = RoundingMode::certified;  // see mk::BooleanOptions
  std::string grid;
};

// The operation's name as the command spells it ("union-all", ...).
const char* parts_operation_name(PartsOperation op);

// The N-ary operation on the parts (the command's and batch's one path); an intersection-all
// of no parts is invalid input, named by input_name.
BooleanOutput compute_parts(PartsOperation op, const MultiPolygon& parts, const BooleanOptions& options,
                            const std::string& input_name);

void run_parts_command(const PartsCommandOptions& options);

}  // namespace mk::cli
