// Small text helpers shared by the readers and writers: line/column of a byte offset,
// shortest round-trip printing of doubles, JSON string escaping. [RFC8259 §7]
// Preconditions: offsets are within the text they refer to (clamped otherwise).
#pragma once

#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>

namespace mk::io_detail {

// A 1-based line and column (in bytes) inside a text.
struct TextPosition {
  std::size_t line = 1;
  std::size_t column = 1;
};

// Computed only when an error is reported, so the readers' hot loops never track lines.
inline TextPosition text_position(std::string_view text, std::size_t offset) {
  if (offset > text.size()) offset = text.size();
  TextPosition p;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++p.line;
      line_start = i + 1;
    }
  }
  p.column = offset - line_start + 1;
  return p;
}

inline std::string describe_position(std::string_view text, std::size_t offset) {
  const TextPosition p = text_position(text, offset);
  return "line " + std::to_string(p.line) + ", column " + std::to_string(p.column);
}

// Shortest text that reads back as the same double (std::to_chars without a format):
// the writers never lose a bit, and 0.1 stays "0.1". Negative zero is written "0": it is
// the same coordinate, and "-0" only puzzles readers.
// The shortest text of a double is at most 24 characters ("-2.2250738585072014e-308").
inline constexpr std::size_t kMaxDoubleText = 24;

// Writes the text at `at`, which has room for kMaxDoubleText characters; returns its end.
inline char* put_double(char* at, double v) {
  if (v == 0) v = 0;
  return std::to_chars(at, at + kMaxDoubleText, v).ptr;
}

inline void append_double(std::string& out, double v) {
  char buf[32];
  out.append(buf, put_double(buf, v));
}

inline std::string format_double(double v) {
  std::string s;
  append_double(s, v);
  return s;
}

// A JSON string literal, quotes included; control characters become \u00XX escapes.
inline void append_json_string(std::string& out, std::string_view s) {
  out.push_back('"');
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          static constexpr char hex[] = "0123456789abcdef";
          out += "\\u00";
          out.push_back(hex[(c >> 4) & 0xf]);
          out.push_back(hex[c & 0xf]);
        } else {
          out.push_back(c);
        }
    }
  }
  out.push_back('"');
}

// A short excerpt of untrusted text for an error message: at most 32 bytes, so a 100 MB
// line of garbage does not end up in the message.
inline std::string excerpt(std::string_view s) {
  constexpr std::size_t max_len = 32;
  if (s.size() <= max_len) return std::string(s);
  return std::string(s.substr(0, max_len)) + "...";
}

// 'text' in single quotes. Built by appending: GCC 12 warns (-Wrestrict, a false positive)
// on "literal" + std::string&&.
inline std::string quoted(std::string_view text) {
  std::string s;
  s.reserve(text.size() + 2);
  s += '\'';
  s += text;
  s += '\'';
  return s;
}

}  // namespace mk::io_detail
