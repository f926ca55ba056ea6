// One Boolean operation from the shell. [MK89 §3.2] [MK89 §2.3]
// Preconditions: see command.hpp.
#include "cli/command.hpp"

#include <cstdio>

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
std::string format_output(const CommandOptions& o, const Polygon& a, const Polygon& b, const BooleanOutput& r) {
  switch (o.format) {
    case OutputFormat::wkt:
    case OutputFormat::geojson:
      if (r.output.unbounded) {
        throw OutputError(std::string("the result of ") + std::string(operation_name(o.op)) + " of A (" +
                          type_name(a.type) + ") and B (" + type_name(b.type) +
                          ") is unbounded (hole type), which " +
                          (o.format == OutputFormat::wkt ? "WKT" : "GeoJSON") +
                          " cannot express; use --format json (or svg)");
      }
      return with_final_newline(o.format == OutputFormat::wkt ? write_wkt(r.output) : write_geojson(r.output));
    case OutputFormat::native_json:
      return with_final_newline(write_native_json(r.output, r.stats.kernel));
    case OutputFormat::svg:
      return with_final_newline(write_svg(a, b, r.output));
  }
  return {};
}

}  // namespace

void run_command(const CommandOptions& o) {
  if (o.a == "-" && o.b == "-") throw UsageError("A and B cannot both be standard input ('-')");
  Input in_a = read_input(o.a, "A");
  Input in_b = read_input(o.b, "B");
  Polygon& a = in_a.polygon;
  Polygon& b = in_b.polygon;
  if (o.a_type) a.type = *o.a_type;
  if (o.b_type) b.type = *o.b_type;

  BooleanOptions options;
  options.op = o.op;
  options.regular = o.regular;
  options.kernel = o.kernel;
  options.area = o.stats;  // the area is only reported in --stats
  options.area_exact = o.stats;
  options.exact_coordinates = o.format == OutputFormat::native_json;  // only the native format writes them
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
  if (o.stats) {
    const std::string line = stats_json(result, counters) + "\n";
    std::fputs(line.c_str(), stderr);
    std::fflush(stderr);
  }
  const std::string text = format_output(o, a, b, result);
  OutputFile out(o.output);
  out.write(text);
  out.commit();
  const RoundingReport& rounding = result.output.rounding;
  if (!rounding.valid && !result.output.unbounded && o.format != OutputFormat::native_json) {
    throw InvalidOutput(std::string("the written polygons are not valid (OGC) once rounded to doubles") +
                        (rounding.mode == RoundingMode::nearest ? "; without --rounding nearest they are snap-rounded"
                                                                : " (kernel " + result.stats.kernel + " is not exact)"));
  }
}

}  // namespace mk::cli
