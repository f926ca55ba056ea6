// JSON helpers shared by the GeoJSON and native JSON readers: parsing with positioned
// errors, element paths, and exact conversion of JSON numbers to doubles. [RFC8259]
// Preconditions: none; every problem throws mk::InvalidInput prefixed with the format name.
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "io/text_util.hpp"

namespace mk::io_detail {

using Json = nlohmann::json;

inline bool is_blank(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  return text.find_first_not_of(" \t\r\n\f\v") == std::string_view::npos;
}

// The DOM builder of Json::parse, except that a number literal that is not zero but
// underflows to zero as a double (1e-400, or 0. and 330 zeros and a 1) becomes NaN, which
// no JSON number is otherwise: nlohmann reads it as 0 without a word, which would silently
// move a vertex (the WKT reader refuses it too). json_number_to_double refuses it where it
// is a coordinate; elsewhere (properties, bbox) it is ignored like the rest.
class DomMarkingUnderflow : public nlohmann::detail::json_sax_dom_parser<Json> {
 public:
  using Base = nlohmann::detail::json_sax_dom_parser<Json>;
  using Base::Base;
  // Called by sax_parse through the template type, so this hides the base's.
  bool number_float(Json::number_float_t value, const Json::string_t& literal) {
    if (value == 0 && literal.find_first_of("123456789") < literal.find_first_of("eE")) {
      value = std::numeric_limits<double>::quiet_NaN();
    }
    return Base::number_float(value, literal);
  }
};

// Parses JSON; syntax errors become "<format> line L, column C: <reason>", with the line
// and column computed from nlohmann's byte offset so that they match the WKT reader's.
inline Json parse_json(std::string_view text, std::string_view format) {
  if (is_blank(text)) {
    throw InvalidInput(std::string(format) + " line 1, column 1: empty input: expected a JSON "
                                             "object");
  }
  try {
    Json json;
    DomMarkingUnderflow dom(json);
    Json::sax_parse(text.begin(), text.end(), &dom);  // errors throw, as in Json::parse
    return json;
  } catch (const Json::parse_error& e) {
    // e.byte is the 1-based index of the last byte read, i.e. the offending one.
    const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
    const std::string what = e.what();
    std::string reason = what;
    const std::size_t column = what.find(", column ");
    const std::size_t colon = column == std::string::npos ? what.find("] ") : what.find(": ", column);
    if (colon != std::string::npos) reason = what.substr(colon + 2);
    throw InvalidInput(std::string(format) + " " + describe_position(text, offset) + ": " + reason);
  } catch (const Json::exception& e) {
    // Number overflow (out_of_range.406) carries no position; its text names the number.
    const std::string what = e.what();
    const std::size_t bracket = what.find("] ");
    throw InvalidInput(std::string(format) + ": " +
                       (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  }
}

inline std::string json_type_name(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "a string";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::binary: return "binary data";
    case Json::value_t::discarded: return "nothing";
    default: return "a number";
  }
}

inline std::string key_path(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

inline std::string index_path(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

// The double a JSON number denotes. Floating literals are rounded to nearest by the
// parser, as every JSON reader does; integers must be exactly representable, because a
// silently rounded integer coordinate is a different input. Returns false (and a reason)
// for non-numbers, inexact integers and non-finite values.
inline bool json_number_to_double(const Json& j, double& out, std::string& problem) {
  switch (j.type()) {
    case Json::value_t::number_float:
      out = j.get<double>();
      if (std::isnan(out)) {  // see DomMarkingUnderflow
        problem = "coordinate is not representable as a double (not zero, but too small in magnitude: it "
                  "would be read as 0)";
        return false;
      }
      if (!std::isfinite(out)) {
        problem = "coordinate is not a finite number";
        return false;
      }
      return true;
    case Json::value_t::number_integer: {
      const auto i = j.get<std::int64_t>();
      out = static_cast<double>(i);
      // 2^63 is the first double outside int64; below it the round trip is exact or not.
      if (out >= 9223372036854775808.0 || static_cast<std::int64_t>(out) != i) {
        problem = "integer coordinate " + std::to_string(i) +
                  " is not exactly a double; only doubles are supported as input coordinates";
        return false;
      }
      return true;
    }
    case Json::value_t::number_unsigned: {
      const auto u = j.get<std::uint64_t>();
      out = static_cast<double>(u);
      if (out >= 18446744073709551616.0 || static_cast<std::uint64_t>(out) != u) {
        problem = "integer coordinate " + std::to_string(u) +
                  " is not exactly a double; only doubles are supported as input coordinates";
        return false;
      }
      return true;
    }
    default:
      problem = "expected a number, found " + json_type_name(j);
      return false;
  }
}

}  // namespace mk::io_detail
