// One Boolean operation from the shell. [MK89 §3.2] [MK89 §2.3]
// Preconditions: see command.hpp.
#include "cli/command.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <tuple>

#include "api/mkbool.hpp"
#include "cli/exit_codes.hpp"
#include "cli/inputs.hpp"
#include "cli/output_file.hpp"
#include "cli/stats.hpp"
#include "io/geojson.hpp"
#include "io/native_json.hpp"
#include "io/parts.hpp"
#include "io/svg.hpp"
#include "io/wkt.hpp"

namespace mk::cli {

namespace {

std::string type_name(PolygonType t) { return t == PolygonType::island ? "island" : "hole"; }

// Text files end in a newline, so that shells and `cat` show the output cleanly.
std::string with_final_newline(std::string text) {
  if (text.empty() || text.back() != '\n') text += '\n';
  return text;
}

// The result's text in the requested format. An unbounded result has no WKT or GeoJSON
// form (both describe finite areas), so it is refused with the way out rather than cut down
// to its bounded part.
std::string format_output(OutputFormat format, const std::string& what, const Polygon& a, const Polygon& b,
                          const BooleanOutput& r, unsigned threads) {
  switch (format) {
    case OutputFormat::wkt:
    case OutputFormat::geojson:
      if (r.output.unbounded) {
        throw OutputError("the result of " + what + " is unbounded (hole type), which " +
                          (format == OutputFormat::wkt ? "WKT" : "GeoJSON") +
                          " cannot express; use --format json (or svg)");
      }
      return with_final_newline(format == OutputFormat::wkt ? write_wkt(r.output, threads) : write_geojson(r.output));
    case OutputFormat::native_json:
      return with_final_newline(write_native_json(r.output, r.stats.kernel));
    case OutputFormat::svg:
      return with_final_newline(write_svg(a, b, r.output));
  }
  return {};
}

// Statistics: one JSON line on standard error.
// Returns 0, or the errno of a failed write (standard error on a full disk): the caller
// reports it after the result is written, so asked-for statistics are never lost with exit 0.
int print_stats(const BooleanOutput& result, const PredicateCounters& counters) {
  const std::string line = stats_json(result, counters) + "\n";
  if (std::fputs(line.c_str(), stderr) == EOF || std::fflush(stderr) != 0) return errno != 0 ? errno : EIO;
  return 0;
}

void throw_if_stats_lost(int stats_lost) {
  if (stats_lost) throw OutputError(std::string("cannot write the statistics to standard error: ") + std::strerror(stats_lost));
}

// Exit 4 after the output is written when the written polygons are not valid once rounded
// (--rounding nearest, or a kernel that is not exact).
void throw_if_written_invalid(const BooleanOutput& result, OutputFormat format) {
  const RoundingReport& rounding = result.output.rounding;
  if (!rounding.valid && !result.output.unbounded && format != OutputFormat::native_json) {
    throw InvalidOutput(std::string("the written polygons are not valid (OGC) once rounded to doubles") +
                        (rounding.mode == RoundingMode::nearest ? std::string("; without --rounding nearest they are snap-rounded")
                         : !rounding.failure.empty()            ? "; snap rounding failed: " + rounding.failure
                                                                : " (kernel " + result.stats.kernel + " is not exact)"));
  }
}

}  // namespace

void run_command(const CommandOptions& o) {
  if (o.a == "-" && o.b == "-") throw UsageError("A and B cannot both be standard input ('-')");
  Input in_a;
  Input in_b;
  if (o.fill_rule) {  // any rings: read as parts, unchecked
    for (auto [in, arg, role] : {std::tuple{&in_a, &o.a, "A"}, std::tuple{&in_b, &o.b, "B"}}) {
      PartsInput parts = read_parts(*arg, role);
      in->polygon = fill_rule_polygon(parts.parts, *o.fill_rule);
      in->name = std::move(parts.name);
    }
  } else {
    in_a = read_input(o.a, "A");
    in_b = read_input(o.b, "B");
  }
  Polygon& a = in_a.polygon;
  Polygon& b = in_b.polygon;
  if (o.a_type) a.type = *o.a_type;
  if (o.b_type) b.type = *o.b_type;

  BooleanOptions options;
  options.op = o.op;
  options.regular = o.regular;
  options.kernel = o.kernel;
  options.area = o.stats;  // the area is only reported in --stats
  options.threads = o.threads;
  options.area_exact = o.stats;
  options.exact_coordinates = o.format == OutputFormat::native_json;  // only the native format writes them
  options.fill_rule = o.fill_rule;
  options.rounding = o.rounding;
  options.grid = o.grid;
  PredicateCounters::reset();
  BooleanOutput result;
  try {
    if (in_a.exact || in_b.exact) {
      // Exact coordinates (a result fed back in): computed over rationals.
      result = compute(in_a.exact ? *in_a.exact : exact_polygon(a), in_b.exact ? *in_b.exact : exact_polygon(b), options);
    } else {
      result = compute(a, b, options);
    }
  } catch (const CrossingEdges& e) {
    // Native JSON input is not checked while read (it means what the paper says), so its
    // crossing edges are found here; named as the reader names them.
    const Input& in = e.polygon() == 0 ? in_a : in_b;
    throw InvalidInput(in.name + ": " + describe_crossing(e, in.polygon, in.ring_names));
  }
  const PredicateCounters counters = PredicateCounters::read();

  // Statistics first: they describe the operation, which succeeded even when its result
  // cannot be written in the requested format.
  // A failed write of them is an error, reported after the result is written.
  const int stats_lost = o.stats ? print_stats(result, counters) : 0;
  const std::string what =
      std::string(operation_name(o.op)) + " of A (" + type_name(a.type) + ") and B (" + type_name(b.type) + ")";
  OutputFile out(o.output);
  out.write(format_output(o.format, what, a, b, result, o.threads));
  out.commit();
  throw_if_stats_lost(stats_lost);
  throw_if_written_invalid(result, o.format);
}

const char* parts_operation_name(PartsOperation op) {
  switch (op) {
    case PartsOperation::union_all: return "union-all";
    case PartsOperation::intersection_all: return "intersection-all";
    case PartsOperation::make_valid: return "make-valid";
  }
  return "?";
}

BooleanOutput compute_parts(PartsOperation op, const MultiPolygon& parts, const BooleanOptions& options,
                            const std::string& input_name) {
  switch (op) {
    case PartsOperation::union_all: return union_all(parts, options);
    case PartsOperation::intersection_all:
      if (parts.empty()) throw InvalidInput(input_name + ": intersection-all needs at least one polygon");
      return intersection_all(parts, options);
    case PartsOperation::make_valid: return make_valid(parts, options);
  }
  throw std::logic_error("unknown parts operation");
}

void run_parts_command(const PartsCommandOptions& o) {
  const PartsInput in = read_parts(o.input, "INPUT");
  BooleanOptions options;
  options.kernel = o.kernel;
  options.area = o.stats;
  options.area_exact = o.stats;
  options.exact_coordinates = o.format == OutputFormat::native_json;
  options.fill_rule = o.fill_rule;
  options.regular = o.regular;
  options.rounding = o.rounding;
  options.grid = o.grid;
  PredicateCounters::reset();
  const BooleanOutput result = compute_parts(o.op, in.parts, options, in.name);
  const char* what = parts_operation_name(o.op);
  const PredicateCounters counters = PredicateCounters::read();
  const int stats_lost = o.stats ? print_stats(result, counters) : 0;
  const Polygon drawn = fill_rule_polygon(in.parts, o.fill_rule.value_or(FillRule::evenodd));
  OutputFile out(o.output);
  out.write(format_output(o.format, what, drawn, Polygon{}, result, options.threads));
  out.commit();
  throw_if_stats_lost(stats_lost);
  throw_if_written_invalid(result, o.format);
}

}  // namespace mk::cli
