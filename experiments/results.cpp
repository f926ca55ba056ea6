// The results CSV: RFC 4180 quoting for the message column, shortest round-trip doubles.
// [MK89 §3.2]
// Preconditions: none.
#include "experiments/results.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace mk::experiments {

const std::vector<std::string_view>& csv_columns() {
  static const std::vector<std::string_view> cols{
      "case",         "generator",       "variant",   "params",          "seed",
      "size",         "op",              "regular",   "kernel",          "verdict",
      "area_error",   "symdiff_area",    "exact_area", "op_ns",          "predicate_calls",
      "predicate_fallbacks", "predicate_stages", "vertices_in", "crossings", "vertices_out", "message",
      "rounding_bound", "oracle_agrees", "geos_valid", "exact_valid",
      "nearest_valid", "certified_snapped", "certified_valid", "snap_displacement"};
  return cols;
}

std::string csv_header() {
  std::string out;
  for (const auto c : csv_columns()) {
    if (!out.empty()) out += ',';
    out += c;
  }
  return out;
}

namespace {

std::string number(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

template <class T>
std::string opt(const std::optional<T>& v) {
  if (!v) return "";
  if constexpr (std::is_floating_point_v<T>) return number(*v);
  else return std::to_string(*v);
}

std::string flag(const std::optional<bool>& v) { return v ? (*v ? "true" : "false") : ""; }

std::optional<bool> parse_flag(const std::string& s) {
  if (s.empty()) return std::nullopt;
  if (s != "true" && s != "false") throw std::runtime_error("not true or false: '" + s + "'");
  return s == "true";
}

std::string csv_quoted(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"') out += "\"\"";
    else if (c == '\n' || c == '\r') out += ' ';
    else out += c;
  }
  return out + "\"";
}

std::vector<std::string> split_csv(std::string_view line) {
  std::vector<std::string> out;
  std::string cur;
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        cur += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      out.push_back(std::move(cur));
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(std::move(cur));
  return out;
}

template <class T>
std::optional<T> parse_opt(const std::string& s) {
  if (s.empty()) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>) {
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
  }
  T v{};
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) throw std::runtime_error("not a number: '" + s + "'");
  return v;
}

}  // namespace

std::string to_csv(const ResultRow& r) {
  std::string out;
  out += std::to_string(r.case_index) + ',' + r.generator + ',' + r.variant + ',' + r.params + ',' +
         std::to_string(r.seed) + ',' + std::to_string(r.size) + ',' + r.op + ',' + (r.regular ? "true" : "false") +
         ',' + r.kernel + ',' + std::string(verdict_name(r.verdict)) + ',' + opt(r.area_error) + ',' +
         opt(r.symdiff_area) + ',' + opt(r.exact_area) + ',' + opt(r.op_ns) + ',' + opt(r.predicate_calls) + ',' +
         opt(r.predicate_fallbacks) + ',' + r.predicate_stages + ',' + opt(r.vertices_in) + ',' + opt(r.crossings) +
         ',' + opt(r.vertices_out) + ',' + csv_quoted(r.message) + ',' + opt(r.rounding_bound) + ',' +
         flag(r.oracle_agrees) + ',' + flag(r.geos_valid) + ',' + flag(r.exact_valid) + ',' +
         flag(r.nearest_valid) + ',' + flag(r.certified_snapped) + ',' + flag(r.certified_valid) + ',' +
         opt(r.snap_displacement);
  return out;
}

ResultRow parse_csv_row(std::string_view line) {
  const auto f = split_csv(line);
  if (f.size() != csv_columns().size()) {
    throw std::runtime_error("expected " + std::to_string(csv_columns().size()) + " fields, found " +
                             std::to_string(f.size()));
  }
  ResultRow r;
  r.case_index = *parse_opt<std::uint64_t>(f[0]);
  r.generator = f[1];
  r.variant = f[2];
  r.params = f[3];
  r.seed = *parse_opt<std::uint64_t>(f[4]);
  r.size = *parse_opt<std::uint64_t>(f[5]);
  r.op = f[6];
  r.regular = f[7] == "true";
  r.kernel = f[8];
  const auto v = parse_verdict(f[9]);
  if (!v) throw std::runtime_error("unknown verdict '" + f[9] + "'");
  r.verdict = *v;
  r.area_error = parse_opt<double>(f[10]);
  r.symdiff_area = parse_opt<double>(f[11]);
  r.exact_area = parse_opt<double>(f[12]);
  r.op_ns = parse_opt<std::int64_t>(f[13]);
  r.predicate_calls = parse_opt<std::int64_t>(f[14]);
  r.predicate_fallbacks = parse_opt<std::int64_t>(f[15]);
  r.predicate_stages = f[16];
  r.vertices_in = parse_opt<std::int64_t>(f[17]);
  r.crossings = parse_opt<std::int64_t>(f[18]);
  r.vertices_out = parse_opt<std::int64_t>(f[19]);
  r.message = f[20];
  r.rounding_bound = parse_opt<double>(f[21]);
  r.oracle_agrees = parse_flag(f[22]);
  r.geos_valid = parse_flag(f[23]);
  r.exact_valid = parse_flag(f[24]);
  r.nearest_valid = parse_flag(f[25]);
  r.certified_snapped = parse_flag(f[26]);
  r.certified_valid = parse_flag(f[27]);
  r.snap_displacement = parse_opt<double>(f[28]);
  return r;
}

std::vector<ResultRow> read_results(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  if (!std::getline(in, line) || line != csv_header()) {
    throw std::runtime_error(path + ": line 1 is not the results header (" + csv_header() + ")");
  }
  std::vector<ResultRow> rows;
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    try {
      rows.push_back(parse_csv_row(line));
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ":" + std::to_string(n) + ": " + e.what());
    }
  }
  return rows;
}

std::vector<ResultRow> read_results_dir(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && name.rfind("results", 0) == 0 && e.path().extension() == ".csv") {
      files.push_back(e.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<ResultRow> rows;
  for (const auto& f : files) {
    auto part = read_results(f);
    rows.insert(rows.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
  }
  return rows;
}

}  // namespace mk::experiments
