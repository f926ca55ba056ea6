// The mkbool command: argument parsing, dispatch to the single-operation and batch forms,
// and the mapping from errors to exit codes and `mkbool: error: ...` messages (issue 3).
// [MK89 §3.2] (procedure polygonoperation: inputs, types, operation, regularity)
// Preconditions: none.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <new>
#include <string>

#include "api/mkbool.hpp"
#include "arithmetic/snap_grid.hpp"
#include "cli/batch.hpp"
#include "cli/command.hpp"
#include "cli/exit_codes.hpp"
#include "cli/heap.hpp"

namespace mk::cli {
namespace {

constexpr const char* usage_lines =
    "usage: mkbool OP A B [--kernel K] [--non-regular] [--a-type island|hole] [--b-type island|hole]\n"
    "                     [--format wkt|geojson|json|svg] [-o FILE] [--stats] [--threads N]\n"
    "                     [--fill-rule evenodd|nonzero|positive|negative|union]\n"
    "                     [--rounding certified|nearest] [--grid G]\n"
    "       mkbool union-all|intersection-all|make-valid INPUT [--fill-rule R] [--non-regular] [--kernel K]\n"
    "                     [--rounding certified|nearest] [--grid G]\n"
    "                     [--format wkt|geojson|json|svg] [-o FILE] [--stats]\n"
    "       mkbool batch FILE.jsonl [--kernel K] [--non-regular] [-o FILE]\n"
    "       mkbool --help | --version\n";

constexpr const char* exit_code_help =
    "A and B: a file (.wkt, .geojson, .json, else the content decides), '-' for standard\n"
    "input (at most one), or inline WKT text.\n"
    "batch: reads JSON Lines {\"id\", \"op\", \"a_wkt\", \"b_wkt\"} and writes one JSON line per\n"
    "case (see 'mkbool batch --help').\n"
    "Exit codes: 0 success; 1 other failure (unwritable output, an unbounded result as\n"
    "WKT/GeoJSON, kernel failure); 2 usage error; 3 invalid input; 4 the output was written\n"
    "but is not a valid polygon once rounded (only with --rounding nearest or an inexact kernel).\n";

int fail(ExitCode code, const std::string& message) {
  std::fprintf(stderr, "mkbool: error: %s\n", message.c_str());
  return static_cast<int>(code);
}

// Every kernel built, checked while parsing so that a misspelt name is a usage error
// before any input is read.
CLI::Validator kernel_validator() {
  return CLI::Validator(
      [](std::string& name) -> std::string {
        std::string known;
        for (const auto k : kernel_names()) {
          if (name == k) return {};
          known += (known.empty() ? "" : ", ") + std::string(k);
        }
        return "unknown kernel '" + name + "' (built: " + known + ")";
      },
      "KERNEL", "kernel");
}

// A grid spacing the library accepts (a positive decimal or fraction), checked while parsing.
CLI::Validator grid_validator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          (void)SnapGrid::parse(text);
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
        return {};
      },
      "G", "grid");
}

const std::map<std::string, RoundingMode>& rounding_modes() {
  static const std::map<std::string, RoundingMode> modes{{"certified", RoundingMode::certified},
                                                         {"nearest", RoundingMode::nearest}};
  return modes;
}

constexpr const char* rounding_help =
    "how coordinates are rounded to doubles: certified (default: the nearest doubles when the result so "
    "rounded is a valid polygon, checked exactly, else snap rounding onto the power-of-two grid at the scale of "
    "the largest coordinate) or nearest (the nearest doubles, valid or not: exit code 4 when not)";
constexpr const char* grid_help =
    "snap-round the result onto multiples of G (a positive decimal like 0.001 or 1e-3, or a fraction p/q, taken "
    "exactly), like shapely's grid_size";

std::string kernel_help() {
  std::string names;
  for (const auto k : kernel_names()) names += (names.empty() ? "" : ", ") + std::string(k);
  return "arithmetic kernel: " + names + " (default " + std::string(default_kernel()) + ")";
}

// CLI11 reports help and version as exceptions with exit code 0, and parse errors with
// its own codes; the command's contract is 2 for every usage error.
// Help and version that cannot be written (standard output on a full disk) are exit 1.
int parse_error(const CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
    const int code = app.exit(e);
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0) {
      std::fprintf(stderr, "mkbool: error: cannot write to standard output\n");
      return static_cast<int>(ExitCode::failure);
    }
    return code;
  }
  std::fprintf(stderr, "mkbool: error: %s (see mkbool --help)\n", e.what());
  return static_cast<int>(ExitCode::usage);
}

const std::map<std::string, FillRule>& fill_rules() {
  static const std::map<std::string, FillRule> rules{{"evenodd", FillRule::evenodd},
                                                     {"nonzero", FillRule::nonzero},
                                                     {"positive", FillRule::positive},
                                                     {"negative", FillRule::negative},
                                                     {"union", FillRule::union_}};
  return rules;
}

const std::map<std::string, OutputFormat>& output_formats() {
  static const std::map<std::string, OutputFormat> formats{{"wkt", OutputFormat::wkt},
                                                           {"geojson", OutputFormat::geojson},
                                                           {"json", OutputFormat::native_json},
                                                           {"svg", OutputFormat::svg}};
  return formats;
}

constexpr const char* fill_rule_help =
    "read the input's rings in their given directions, crossing freely, by their winding numbers: evenodd "
    "(odd), nonzero, positive, negative, or union (every shell counterclockwise and every hole clockwise, "
    "then nonzero: the union of the parts)";

// mkbool union-all | intersection-all | make-valid INPUT: the parts of one input in one
// arrangement.
int run_parts_form(int argc, char** argv) {
  const std::string verb = argv[1];
  const std::map<std::string, PartsOperation> verbs{{"union-all", PartsOperation::union_all},
                                                    {"intersection-all", PartsOperation::intersection_all},
                                                    {"make-valid", PartsOperation::make_valid}};
  CLI::App app(verb == "make-valid"
                   ? "The valid polygon of the input's region under a fill rule (default evenodd).\n"
                   : "The " + std::string(verb == "union-all" ? "union" : "intersection") +
                         " of every polygon of the input (MULTIPOLYGON, GEOMETRYCOLLECTION, GeoJSON\n"
                         "FeatureCollection, or a file of one WKT per line), in one arrangement of all rings.\n",
               "mkbool " + verb);
  PartsCommandOptions o;
  o.op = verbs.at(verb);
  std::string rule;
  std::string format = "wkt";
  app.add_option("INPUT", o.input, "file, '-' or inline WKT")->required();
  app.add_option("--fill-rule", rule, fill_rule_help)->check(CLI::IsMember(fill_rules()));
  bool non_regular = false;
  app.add_flag("--non-regular", non_regular,
               "closed-set operation of the parts' closures (intersection-all keeps where parts only touch)");
  app.add_option("--kernel", o.kernel, kernel_help())->check(kernel_validator());
  app.add_option("--format", format, "output format: wkt (default), geojson, json (native, exact) or svg")
      ->check(CLI::IsMember(output_formats()));
  app.add_option("-o,--output", o.output, "output file (written whole or not at all); default standard output");
  app.add_flag("--stats", o.stats, "print one JSON line of statistics on standard error");
  std::string rounding = "certified";
  app.add_option("--rounding", rounding, rounding_help)->check(CLI::IsMember(rounding_modes()));
  app.add_option("--grid", o.grid, grid_help)->check(grid_validator());
  try {
    app.parse(argc - 1, argv + 1);
  } catch (const CLI::ParseError& e) {
    return parse_error(app, e);
  }
  if (!rule.empty()) o.fill_rule = fill_rules().at(rule);
  o.regular = !non_regular;
  o.format = output_formats().at(format);
  o.rounding = rounding_modes().at(rounding);
  if (o.rounding == RoundingMode::nearest && !o.grid.empty()) {
    return fail(ExitCode::usage, "--grid snaps the result, which --rounding nearest does not (see mkbool " + verb + " --help)");
  }
  run_parts_command(o);
  return static_cast<int>(ExitCode::success);
}

int run_batch_form(int argc, char** argv) {
  CLI::App app("Runs one Boolean operation per JSON line. Each input line is an object with \"id\",\n"
               "\"op\" (intersection, union, difference, symdifference or xor), \"a_wkt\" and \"b_wkt\"\n"
               "(or \"a\" and \"b\": native JSON polygons, exact rationals allowed), or \"op\" union-all,\n"
               "intersection-all or make-valid with \"wkt\", \"parts\" (an array of WKT) or \"geojson\"; each output line\n"
               "has id, op, kernel, result_wkt, area, area_beyond_double, area_exact, valid, op_ns,\n"
               "snapped, line, result (with --exact-result), and error when that case failed. A failed\n"
               "case never stops the batch.\n",
               "mkbool batch");
  BatchOptions o;
  bool non_regular = false;
  app.add_option("FILE", o.input, "JSON Lines file, or '-' for standard input")->required();
  app.add_option("--kernel", o.kernel, kernel_help())->check(kernel_validator());
  app.add_flag("--non-regular", non_regular, "closed-set operations (keep dangling edges and points)");
  bool no_area_exact = false;
  app.add_flag("--no-area-exact", no_area_exact,
               "leave out area_exact (the exact area as a rational), which on results with many crossing points "
               "costs more than the operation; a line's own \"area_exact\": false does the same for that line");
  app.add_flag("--exact-result", o.exact_result,
               "add \"result\": the result as a native JSON polygon with exact coordinates (exact kernels), "
               "which a later line can take as \"a\" or \"b\"; a line's own \"exact_result\" does the same for that line");
  app.add_option("-o,--output", o.output, "output file (written whole or not at all); default standard output");
  std::string rounding = "certified";
  app.add_option("--rounding", rounding, std::string(rounding_help) + "; a line's own \"rounding\" does the same for that line")
      ->check(CLI::IsMember(rounding_modes()));
  app.add_option("--grid", o.grid, std::string(grid_help) + "; a line's own \"grid\" does the same for that line")
      ->check(grid_validator());
  try {
    app.parse(argc - 1, argv + 1);  // argv[1] is "batch"
  } catch (const CLI::ParseError& e) {
    return parse_error(app, e);
  }
  o.regular = !non_regular;
  o.area_exact = !no_area_exact;
  o.rounding = rounding_modes().at(rounding);
  run_batch(o);
  return static_cast<int>(ExitCode::success);
}

int run_command_form(int argc, char** argv) {
  CLI::App app(std::string("Exact Boolean operations on polygons (Margalit & Knott 1989).\n\n") + usage_lines,
               "mkbool");
  app.footer(exit_code_help);
  app.set_version_flag("--version", std::string("mkbool ") + MK_VERSION);

  CommandOptions o;
  std::string op;
  std::string a_type;
  std::string b_type;
  std::string format = "wkt";
  bool non_regular = false;
  const std::map<std::string, Operation> ops{{"intersection", Operation::intersection},
                                             {"union", Operation::union_},
                                             {"difference", Operation::difference},
                                             {"xor", Operation::symmetric_difference},
                                             {"symdifference", Operation::symmetric_difference}};
  const std::map<std::string, OutputFormat>& formats = output_formats();
  std::string rule;
  const std::map<std::string, PolygonType> types{{"island", PolygonType::island}, {"hole", PolygonType::hole}};

  app.add_option("OP", op, "intersection, union, difference (A minus B) or xor (also: symdifference)")
      ->required()
      ->check(CLI::IsMember(ops));
  app.add_option("A", o.a, "first polygon: file, '-' or inline WKT")->required();
  app.add_option("B", o.b, "second polygon: file, '-' or inline WKT")->required();
  app.add_option("--kernel", o.kernel, kernel_help())->check(kernel_validator());
  app.add_flag("--non-regular", non_regular, "closed-set operations (keep dangling edges and points)");
  app.add_option("--a-type", a_type, "type of A: island or hole (default: from the input; island)")
      ->check(CLI::IsMember(types));
  app.add_option("--b-type", b_type, "type of B: island or hole (default: from the input; island)")
      ->check(CLI::IsMember(types));
  app.add_option("--format", format, "output format: wkt (default), geojson, json (native, exact) or svg")
      ->check(CLI::IsMember(formats));
  app.add_option("-o,--output", o.output, "output file (written whole or not at all); default standard output");
  app.add_flag("--stats", o.stats, "print one JSON line of statistics on standard error");
  app.add_option("--fill-rule", rule, fill_rule_help)->check(CLI::IsMember(fill_rules()));
  app.add_option("--threads", o.threads, "threads for the operation (default 0: every core; the result is the same)")
      ->check(CLI::Range(0u, 1024u));
  std::string rounding = "certified";
  app.add_option("--rounding", rounding, rounding_help)->check(CLI::IsMember(rounding_modes()));
  app.add_option("--grid", o.grid, grid_help)->check(grid_validator());
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return parse_error(app, e);
  }
  o.op = ops.at(op);
  o.regular = !non_regular;
  if (!a_type.empty()) o.a_type = types.at(a_type);
  if (!b_type.empty()) o.b_type = types.at(b_type);
  o.format = formats.at(format);
  if (!rule.empty()) o.fill_rule = fill_rules().at(rule);
  o.rounding = rounding_modes().at(rounding);
  if (o.rounding == RoundingMode::nearest && !o.grid.empty()) {
    return fail(ExitCode::usage, "--grid snaps the result, which --rounding nearest does not (see mkbool --help)");
  }
  run_command(o);
  return static_cast<int>(ExitCode::success);
}

int run(int argc, char** argv) {
  try {
    if (argc > 1 && std::strcmp(argv[1], "batch") == 0) return run_batch_form(argc, argv);
    for (const char* verb : {"union-all", "intersection-all", "make-valid"}) {
      if (argc > 1 && std::strcmp(argv[1], verb) == 0) return run_parts_form(argc, argv);
    }
    return run_command_form(argc, argv);
  } catch (const UsageError& e) {
    return fail(ExitCode::usage, e.what());
  } catch (const InvalidInput& e) {
    return fail(ExitCode::invalid_input, e.what());
  } catch (const KernelFailure& e) {
    return fail(ExitCode::failure, std::string("the kernel failed (inexact arithmetic): ") + e.what() +
                                       "; an exact kernel (--kernel " + std::string(default_kernel()) +
                                       ") never does");
  } catch (const OutputError& e) {
    return fail(ExitCode::failure, e.what());
  } catch (const InvalidOutput& e) {
    std::fprintf(stderr, "mkbool: warning: %s\n", e.what());
    return static_cast<int>(ExitCode::invalid_output);
  } catch (const std::bad_alloc&) {
    return fail(ExitCode::failure, "out of memory");
  } catch (const std::exception& e) {
    return fail(ExitCode::failure, e.what());
  }
}

}  // namespace
}  // namespace mk::cli

int main(int argc, char** argv) {
  // Freed memory kept, and the heap's top advised for huge pages (cli/heap.hpp): blob 1e6 end
  // to end 1.3-1.8 s -> 0.5-0.9 s where page faults are dear (bench/README.md, "The
  // command's heap").
  mk::cli::prepare_heap();
  return mk::cli::run(argc, argv);
}
