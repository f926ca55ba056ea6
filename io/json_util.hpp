// JSON helpers shared by the GeoJSON and native JSON readers: parsing with positioned
// errors, element paths, and exact conversion of JSON numbers to doubles. [RFC8259]
// Preconditions: none; every problem throws mk::InvalidInput prefixed with the format name.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "io/text_util.hpp"

namespace mk::io_detail {

using Json = nlohmann::json;

inline bool is_blank(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  return text.find_first_not_of(" \t\r\n\f\v") == std::string_view::npos;
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

// A member name repeated within one object: its path (key_path of the object's path and
// the name) and the name.
struct RepeatedMember {
  std::string path;
  std::string name;
};

// Why a repeated member name is refused.
inline std::string repeated_member_problem(const std::string& name) {
  return "member \"" + excerpt(name) + "\" is repeated in its object; JSON leaves open which value counts (RFC 8259 §4), so give it once";
}

// The DOM builder of Json::parse, except for two things nlohmann's parser passes over
// without a word:
// - A number literal that is not zero but underflows to zero as a double (1e-400, or 0. and
//   330 zeros and a 1) becomes NaN, which no JSON number is otherwise: nlohmann reads it as
//   0, which would silently move a vertex (the WKT reader refuses it too).
//   json_number_to_double refuses it where it is a coordinate; elsewhere (properties, bbox)
//   it is ignored like the rest.
// - A member name repeated within one object is recorded (its path, as key_path and
//   index_path write it: "features[2].geometry.type"): nlohmann keeps the last value, other
//   readers the first, and RFC 8259 §4 leaves the meaning open, so a reader refuses the
//   repeated members it reads rather than pick one. [RFC8259 §4]
class CheckedDom : public nlohmann::detail::json_sax_dom_parser<Json> {
 public:
  using Base = nlohmann::detail::json_sax_dom_parser<Json>;
  CheckedDom(Json& root, std::vector<RepeatedMember>& repeated) : Base(root), repeated_(&repeated) {}

  // Called by sax_parse through the template type, so these hide the base's.
  bool number_float(Json::number_float_t value, const Json::string_t& literal) {
    if (value == 0 && literal.find_first_of("123456789") < literal.find_first_of("eE")) {
      value = std::numeric_limits<double>::quiet_NaN();
    }
    return value_in_parent() && Base::number_float(value, literal);
  }
  bool null() { return value_in_parent() && Base::null(); }
  bool boolean(bool v) { return value_in_parent() && Base::boolean(v); }
  bool number_integer(Json::number_integer_t v) { return value_in_parent() && Base::number_integer(v); }
  bool number_unsigned(Json::number_unsigned_t v) { return value_in_parent() && Base::number_unsigned(v); }
  bool string(Json::string_t& v) { return value_in_parent() && Base::string(v); }
  bool binary(Json::binary_t& v) { return value_in_parent() && Base::binary(v); }
  bool start_object(std::size_t len) {
    value_in_parent();
    frames_.push_back(kObject);
    objects_.emplace_back();
    return Base::start_object(len);
  }
  bool end_object() {
    frames_.pop_back();
    objects_.pop_back();
    return Base::end_object();
  }
  bool start_array(std::size_t len) {
    value_in_parent();
    frames_.push_back(0);
    return Base::start_array(len);
  }
  bool end_array() {
    frames_.pop_back();
    return Base::end_array();
  }
  bool key(Json::string_t& name) {
    std::vector<std::string>& names = objects_.back();
    if (std::find(names.begin(), names.end(), name) != names.end()) repeated_->push_back({key_path(path(), name), name});
    names.push_back(name);
    return Base::key(name);
  }

 private:
  // Per open container, innermost last: an array's count of values so far, or kObject.
  // Objects also have their member names so far, the current one last (arrays, which may
  // nest a million deep, cost one word each).
  static constexpr std::size_t kObject = static_cast<std::size_t>(-1);
  // Counts a value in its array (its index is then the count less one).
  bool value_in_parent() {
    if (!frames_.empty() && frames_.back() != kObject) ++frames_.back();
    return true;
  }
  // The path of the innermost open container.
  std::string path() const {
    std::string p;
    std::size_t object = 0;
    for (std::size_t i = 0; i + 1 < frames_.size(); ++i) {
      p = frames_[i] == kObject ? key_path(p, objects_[object++].back()) : index_path(p, frames_[i] - 1);
    }
    return p;
  }

  std::vector<std::size_t> frames_;
  std::vector<std::vector<std::string>> objects_;
  std::vector<RepeatedMember>* repeated_;
};

// Parses JSON with nlohmann's own errors (Json::parse_error, Json::out_of_range), recording
// the paths of repeated member names in `repeated` (CheckedDom).
inline Json parse_json_dom(std::string_view text, std::vector<RepeatedMember>& repeated) {
  Json json;
  CheckedDom dom(json, repeated);
  Json::sax_parse(text.begin(), text.end(), &dom);  // errors throw, as in Json::parse
  return json;
}

// Parses JSON; syntax errors become "<format> line L, column C: <reason>", with the line
// and column computed from nlohmann's byte offset so that they match the WKT reader's. The
// paths of repeated member names go to `repeated`; without it, any repeated name is refused.
inline Json parse_json(std::string_view text, std::string_view format, std::vector<RepeatedMember>* repeated = nullptr) {
  if (is_blank(text)) {
    throw InvalidInput(std::string(format) + " line 1, column 1: empty input: expected a JSON "
                                             "object");
  }
  std::vector<RepeatedMember> found;
  Json json;
  try {
    json = parse_json_dom(text, found);
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
  if (repeated != nullptr) {
    *repeated = std::move(found);
  } else if (!found.empty()) {
    throw InvalidInput(std::string(format) + " at " + found.front().path + ": " + repeated_member_problem(found.front().name));
  }
  return json;
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
