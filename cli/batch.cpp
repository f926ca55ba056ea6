// Batch mode over JSON Lines. [MK89 §3.2] [MK89 §2.3]
// Preconditions: see batch.hpp.
#include "cli/batch.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <new>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include "api/mkbool.hpp"
#include "cli/command.hpp"
#include "cli/exit_codes.hpp"
#include "cli/inputs.hpp"
#include "cli/output_file.hpp"
#include "cli/stats.hpp"
#include "io/file.hpp"
#include "io/native_json.hpp"
#include "io/parts.hpp"
#include "io/format.hpp"
#include "io/json_util.hpp"
#include "io/wkt.hpp"

namespace mk::cli {

namespace {

using Json = nlohmann::ordered_json;  // output lines: keys in their documented order
// Input lines are parsed into nlohmann::json, whose objects are std::maps: inserting a key
// never moves the values already there. ordered_json's objects are vectors of pairs, which
// copy every value (recursively) when they grow: a deep "id" followed by one more key
// overflowed the stack while the line was being parsed.
using InputJson = nlohmann::json;

// A case that cannot be run; its message goes into the output line's "error".
struct CaseError {
  std::string message;
};

std::optional<Operation> parse_operation(std::string_view name) {
  if (name == "intersection") return Operation::intersection;
  if (name == "union") return Operation::union_;
  if (name == "difference") return Operation::difference;
  if (name == "symdifference" || name == "xor") return Operation::symmetric_difference;
  return std::nullopt;
}

std::optional<PartsOperation> parse_parts_operation(std::string_view name) {
  if (name == "union-all") return PartsOperation::union_all;
  if (name == "intersection-all") return PartsOperation::intersection_all;
  if (name == "make-valid") return PartsOperation::make_valid;
  return std::nullopt;
}

std::string member_string(const InputJson& line, const char* key) {
  const auto it = line.find(key);
  if (it == line.end()) throw CaseError{std::string("missing \"") + key + "\""};
  if (!it->is_string()) throw CaseError{std::string("\"") + key + "\" is not a string"};
  return it->get<std::string>();
}

// Read and checked as the command reads WKT (io/parts.hpp): multi-part input is never
// reinterpreted.
Polygon read_case_polygon(const std::string& wkt, const char* key) {
  try {
    PartNames names;
    const MultiPolygon mp = read_wkt(wkt, &names.parts);
    return to_checked_polygon(mp, names);
  } catch (const InvalidInput& e) {
    throw CaseError{std::string(key) + ": " + e.what()};
  }
}

// nlohmann's messages start with "[json.exception.parse_error.101] ", which helps nobody,
// and count lines within the one JSON line, which the output's "line" already gives.
std::string without_exception_id(const char* what) {
  std::string_view s(what);
  if (!s.empty() && s.front() == '[') {
    if (const auto end = s.find("] "); end != std::string_view::npos) s.remove_prefix(end + 2);
  }
  std::string message(s);
  constexpr std::string_view line_one = "at line 1, column ";
  if (const auto at = message.find(line_one); at != std::string::npos) message.replace(at, line_one.size(), "at column ");
  return message;
}

// How deep an echoed id may nest. nlohmann's parser and destructor are iterative, so a
// line of any depth is read and dropped safely, but copying and writing a value recurse once
// per level: a million nested arrays overflow the stack. The id is therefore checked before
// it is copied into the output line, and refused beyond this depth; members the batch
// ignores are never copied.
constexpr std::size_t max_id_depth = 1000;

// Whether j nests more than `limit` arrays or objects deep; iterative.
bool nests_deeper_than(const InputJson& j, std::size_t limit) {
  std::vector<std::pair<const InputJson*, std::size_t>> stack{{&j, 0}};
  while (!stack.empty()) {
    const auto [value, depth] = stack.back();
    stack.pop_back();
    if (!value->is_structured()) continue;
    if (depth + 1 > limit) return true;
    for (const InputJson& child : *value) stack.emplace_back(&child, depth + 1);
  }
  return false;
}

// The options of one case: the command's, then the line's own "area_exact", "exact_result",
// "rounding" and "grid".
BooleanOptions case_options(const InputJson& line, const BatchOptions& options, std::optional<FillRule> rule) {
  BooleanOptions o;
  o.fill_rule = rule;
  o.regular = options.regular;
  o.kernel = options.kernel;
  o.area_exact = options.area_exact;
  if (const auto it = line.find("area_exact"); it != line.end()) {
    if (!it->is_boolean()) throw CaseError{"\"area_exact\" is not true or false"};
    o.area_exact = o.area_exact && it->get<bool>();
  }
  o.exact_coordinates = options.exact_result;
  if (const auto it = line.find("exact_result"); it != line.end()) {
    if (!it->is_boolean()) throw CaseError{"\"exact_result\" is not true or false"};
    o.exact_coordinates = it->get<bool>();
  }
  o.rounding = options.rounding;
  o.grid = options.grid;
  if (const auto it = line.find("rounding"); it != line.end()) {
    if (*it == "certified") {
      o.rounding = RoundingMode::certified;
    } else if (*it == "nearest") {
      o.rounding = RoundingMode::nearest;
    } else {
      throw CaseError{"\"rounding\" is not \"certified\" or \"nearest\""};
    }
  }
  if (const auto it = line.find("grid"); it != line.end()) {
    if (!it->is_string()) throw CaseError{"\"grid\" is not a string (a decimal like \"0.001\" or a fraction \"p/q\")"};
    o.grid = it->get<std::string>();
  }
  if (o.rounding == RoundingMode::nearest && !o.grid.empty()) throw CaseError{"\"grid\" snaps, which rounding nearest does not"};
  return o;
}

// A binary operation: "a_wkt" and "b_wkt", or "a" and "b" in the native JSON form, whose
// coordinates may be exact rationals (an exact result fed back in).
BooleanOutput run_binary_case(const InputJson& line, Operation op, BooleanOptions o) {
  o.op = op;
  const std::optional<FillRule> rule = o.fill_rule;
  const bool native = line.contains("a") || line.contains("b");
  if (native && (line.contains("a_wkt") || line.contains("b_wkt"))) {
    throw CaseError{"give the polygons as \"a_wkt\" and \"b_wkt\" or as \"a\" and \"b\", not both"};
  }
  if (native && rule) throw CaseError{"\"fill_rule\" reads \"a_wkt\" and \"b_wkt\" (any rings), not \"a\" and \"b\""};
  if (!native && !line.contains("a_wkt") && (line.contains("wkt") || line.contains("parts") || line.contains("geojson"))) {
    throw CaseError{"missing \"a_wkt\" (\"wkt\", \"parts\" and \"geojson\" are the input of union-all, intersection-all "
                    "and make-valid)"};
  }
  const auto read = [&](const char* key) {
    if (!rule) return read_case_polygon(member_string(line, key), key);
    try {
      return fill_rule_polygon(read_wkt(member_string(line, key)), *rule);
    } catch (const InvalidInput& e) {
      throw CaseError{std::string(key) + ": " + e.what()};
    }
  };
  const auto read_native = [&](const char* key) {
    const auto it = line.find(key);
    if (it == line.end()) throw CaseError{std::string("missing \"") + key + "\""};
    if (!it->is_object()) throw CaseError{std::string("\"") + key + "\" is not a native JSON polygon object"};
    try {
      return read_native_json_exact(it->dump());
    } catch (const InvalidInput& e) {
      throw CaseError{std::string(key) + ": " + e.what()};
    }
  };
  if (native) {
    const ExactPolygon a = read_native("a"), b = read_native("b");
    return compute(a, b, o);
  }
  const Polygon a = read("a_wkt"), b = read("b_wkt");
  return compute(a, b, o);
}

// union-all, intersection-all or make-valid of the parts of one input, given as exactly one
// of "wkt" (a WKT geometry, its polygons the parts), "parts" (an array of WKT geometries)
// or "geojson" (a GeoJSON object: a FeatureCollection, a geometry, a Feature).
BooleanOutput run_parts_case(const InputJson& line, PartsOperation op, const BooleanOptions& o) {
  const int given = int(line.contains("wkt")) + int(line.contains("parts")) + int(line.contains("geojson"));
  if (given == 0) {
    throw CaseError{"missing the input: \"wkt\", \"parts\" (an array of WKT) or \"geojson\" (\"a_wkt\" and \"b_wkt\" are "
                    "a binary operation's)"};
  }
  if (given > 1) throw CaseError{"give the input as one of \"wkt\", \"parts\" and \"geojson\", not several"};
  MultiPolygon parts;
  const char* key = line.contains("wkt") ? "wkt" : line.contains("parts") ? "parts" : "geojson";
  try {
    if (line.contains("wkt")) {
      parts = read_parts_input(member_string(line, "wkt"), "input.wkt");
    } else if (line.contains("geojson")) {
      const InputJson& g = line["geojson"];
      if (!g.is_object()) throw CaseError{"\"geojson\" is not a GeoJSON object"};
      parts = read_parts_input(g.dump(), "input.geojson");
    } else {
      const InputJson& list = line["parts"];
      if (!list.is_array()) throw CaseError{"\"parts\" is not an array of WKT strings"};
      for (std::size_t i = 0; i < list.size(); ++i) {
        if (!list[i].is_string()) throw CaseError{"\"parts\"[" + std::to_string(i) + "] is not a WKT string"};
        try {
          for (OgcPolygon& p : read_wkt(list[i].get<std::string>())) parts.push_back(std::move(p));
        } catch (const InvalidInput& e) {
          throw InvalidInput("[" + std::to_string(i) + "]: " + e.what());
        }
      }
    }
  } catch (const InvalidInput& e) {
    throw CaseError{std::string(key) + (key[0] == 'p' ? "" : ": ") + e.what()};
  }
  return compute_parts(op, parts, o, key);  // its InvalidInput becomes the line's error
}

// The output line's results.
void write_case_result(const BooleanOutput& r, bool want_result, Json& out) {
  out["kernel"] = r.stats.kernel;
  out["valid"] = is_output_valid(r.output);
  out["snapped"] = r.output.rounding.snapped;
  out["op_ns"] = r.stats.op_ns;
  // JSON has no infinity: an area beyond the largest double is null and flagged.
  out["area"] = r.stats.area && std::isfinite(*r.stats.area) ? Json(*r.stats.area) : Json(nullptr);
  out["area_beyond_double"] = r.stats.area_beyond_double;
  out["area_exact"] = r.stats.area_exact ? Json(*r.stats.area_exact) : Json(nullptr);
  // The result in the native JSON form (exact coordinates from exact kernels), itself a
  // valid "a" or "b" of a later line.
  if (want_result) out["result"] = Json::parse(write_native_json(r.output, r.stats.kernel));
  // Inputs of WKT are islands, so the result is bounded; native input may be unbounded, and
  // then only "result" can hold it.
  if (r.output.unbounded) {
    if (!want_result) throw CaseError{"the result is unbounded and has no WKT form (ask for \"exact_result\")"};
    return;
  }
  out["result_wkt"] = write_wkt(r.output);
}

// Fills `out` for one case; throws CaseError when the case fails.
void run_case(std::string_view text, const BatchOptions& options, Json& out) {
  InputJson line;
  std::vector<io_detail::RepeatedMember> repeated;
  try {
    line = io_detail::parse_json_dom(text, repeated);
  } catch (const InputJson::exception& e) {  // syntax, or a number beyond the doubles
    throw CaseError{"malformed JSON: " + without_exception_id(e.what())};
  }
  if (!repeated.empty()) {
    throw CaseError{"at " + repeated.front().path + ": " + io_detail::repeated_member_problem(repeated.front().name)};
  }
  if (!line.is_object()) throw CaseError{"a line must be a JSON object"};
  if (const auto id = line.find("id"); id != line.end()) {
    if (nests_deeper_than(*id, max_id_depth)) {
      throw CaseError{"\"id\" nests deeper than " + std::to_string(max_id_depth) + " levels"};
    }
    out["id"] = Json(*id);
  }
  const std::string op_name = member_string(line, "op");
  out["op"] = op_name;
  const auto op = parse_operation(op_name);
  const auto parts_op = parse_parts_operation(op_name);
  if (!op && !parts_op) {
    throw CaseError{"unknown op '" + op_name +
                    "' (expected intersection, union, difference, symdifference, xor, union-all, intersection-all or make-valid)"};
  }
  // "fill_rule": the inputs are any rings, read by the rule (io/format.hpp, unchecked).
  std::optional<FillRule> rule;
  if (line.contains("fill_rule")) {
    const std::string name = member_string(line, "fill_rule");
    for (const FillRule r : {FillRule::evenodd, FillRule::nonzero, FillRule::positive, FillRule::negative, FillRule::union_}) {
      if (name == fill_rule_name(r)) rule = r;
    }
    if (!rule) throw CaseError{"unknown fill_rule '" + name + "' (expected evenodd, nonzero, positive, negative or union)"};
  }
  const BooleanOptions o = case_options(line, options, rule);
  BooleanOutput r;
  try {
    r = parts_op ? run_parts_case(line, *parts_op, o) : run_binary_case(line, *op, o);
  } catch (const std::invalid_argument& e) {  // a kernel that takes doubles only, given rationals
    throw CaseError{e.what()};
  } catch (const InvalidInput& e) {
    throw CaseError{e.what()};
  } catch (const KernelFailure& e) {
    throw CaseError{"kernel " + out["kernel"].get<std::string>() + " failed: " + e.what()};
  }
  write_case_result(r, o.exact_coordinates, out);
}
std::string_view strip_line_end(std::string_view s) {
  if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
  return s;
}

bool is_blank(std::string_view s) { return s.find_first_not_of(" \t\r\f\v") == std::string_view::npos; }

}  // namespace

std::size_t run_batch(const BatchOptions& options) {
  std::string text;
  // JSON Lines are text: a NUL byte means binary data (/dev/zero, /dev/urandom, a binary
  // file), refused at once with its offset instead of read to its end or until memory runs out.
  if (options.input == "-") {
    text = read_text_stream(stdin, "standard input");
  } else {
    text = read_text_file(options.input);
  }
  const std::string kernel(options.kernel.empty() ? default_kernel() : std::string_view(options.kernel));

  OutputFile out(options.output);
  std::size_t failed = 0;
  std::size_t line_number = 0;
  std::string_view rest(text);
  while (!rest.empty()) {
    const std::size_t end = rest.find('\n');
    const std::string_view raw = strip_line_end(rest.substr(0, end));
    rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
    ++line_number;
    if (is_blank(raw)) continue;

    // Every key in its place from the start, so that the lines have one shape.
    Json result = {{"id", nullptr},         {"op", nullptr},
                   {"kernel", kernel},       {"result_wkt", nullptr},
                   {"area", nullptr},        {"area_beyond_double", nullptr},
                   {"area_exact", nullptr},  {"valid", nullptr},
                   {"op_ns", nullptr},       {"snapped", nullptr},
                   {"line", line_number}};
    if (options.exact_result) result["result"] = nullptr;
    try {
      run_case(raw, options, result);
    } catch (const CaseError& e) {
      result["error"] = e.message;
      ++failed;
    } catch (const std::bad_alloc&) {
      result["error"] = "out of memory";
      ++failed;
    } catch (const std::exception& e) {
      result["error"] = e.what();
      ++failed;
    }
    if (result.contains("error")) {
      // A failed case reports no partial result.
      for (const char* key : {"result_wkt", "area", "area_beyond_double", "area_exact", "valid", "op_ns", "snapped"}) result[key] = nullptr;
      if (result.contains("result")) result["result"] = nullptr;
    }
    out.write(result.dump(-1, ' ', false, Json::error_handler_t::replace) + "\n");
  }
  out.commit();
  return failed;
}

}  // namespace mk::cli
