// Resolving the command's polygon arguments into polygons. [MK89 §2.2] [OGC06-103 §7]
// Preconditions: none; every failure is an mk::InvalidInput naming the argument.
#include "cli/inputs.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "core/error.hpp"
#include "io/file.hpp"
#include "io/format.hpp"

namespace mk::cli {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

bool starts_with_word(std::string_view s, std::string_view upper_word) {
  if (s.size() < upper_word.size()) return false;
  for (std::size_t i = 0; i < upper_word.size(); ++i) {
    const char c = s[i];
    const char u = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
    if (u != upper_word[i]) return false;
  }
  return s.size() == upper_word.size() || !is_letter(s[upper_word.size()]);
}

std::string_view skip_space(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  return s;
}

// A keyword of letters, then `(`, EMPTY or a dimension tag: what every WKT geometry starts
// with, and what no ordinary file name looks like. Unknown keywords (LINESTRING) still
// count, so that the reader reports the geometry type instead of a missing file.
bool looks_like_wkt(std::string_view s) {
  s = skip_space(s);
  std::size_t n = 0;
  while (n < s.size() && is_letter(s[n])) ++n;
  if (n == 0) return false;
  s = skip_space(s.substr(n));
  return (!s.empty() && s.front() == '(') || starts_with_word(s, "EMPTY") || starts_with_word(s, "Z") ||
         starts_with_word(s, "M") || starts_with_word(s, "ZM");
}

bool looks_like_json(std::string_view s) {
  s = skip_space(s);
  return !s.empty() && s.front() == '{';
}

bool is_blank(std::string_view s) { return skip_space(s).empty(); }

}  // namespace

InputSource classify_input(const std::string& argument) {
  if (argument == "-") return InputSource::standard_input;
  std::error_code ec;
  if (std::filesystem::exists(argument, ec)) return InputSource::file;
  if (looks_like_wkt(argument) || looks_like_json(argument)) return InputSource::inline_text;
  return InputSource::file;
}

std::string read_standard_input() {
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t got = std::fread(buffer, 1, sizeof buffer, stdin);
    text.append(buffer, got);
    if (got < sizeof buffer) {
      if (std::ferror(stdin)) {
        throw InvalidInput(std::string("cannot read standard input: ") + std::strerror(errno));
      }
      break;
    }
  }
  return text;
}

namespace {

// The text of one argument and how messages name its source; `hint` is the file name that
// helps choose the format (empty: sniff the content).
struct Loaded {
  std::string text;
  std::string where;
  std::string hint;
};

Loaded load_argument(const std::string& argument, const std::string& who) {
  Loaded l;
  switch (classify_input(argument)) {
    case InputSource::standard_input:
      try {
        l.text = read_text_stream(stdin, "standard input");  // stops at a NUL byte (< /dev/zero)
      } catch (const InvalidInput& e) {
        throw InvalidInput(who + ": " + e.what());
      }
      l.where = "standard input";
      break;
    case InputSource::file:
      try {
        l.text = read_text_file(argument);  // stops at a NUL byte: /dev/zero is refused at once
      } catch (const InvalidInput& e) {
        throw InvalidInput(who + ": " + e.what());  // the message already names the path
      }
      l.where = "file '" + argument + "'";
      l.hint = argument;
      break;
    case InputSource::inline_text:
      l.text = argument;
      l.where = looks_like_json(argument) ? "inline JSON" : "inline WKT";
      break;
  }
  if (is_blank(l.text)) {
    // empty_input_message quotes a path; standard input has none.
    const std::string message = empty_input_message(argument);
    throw InvalidInput(who + ": " + (argument == "-" ? "standard input" + message.substr(message.find(" is empty"))
                                                       : message));
  }
  return l;
}

}  // namespace

Input read_input(const std::string& argument, std::string_view role) {
  const std::string who(role);
  const Loaded l = load_argument(argument, who);
  const std::string& text = l.text;
  const std::string& where = l.where;
  const std::string& hint = l.hint;
  Input in;
  in.name = who + " (" + where + ")";
  try {
    PolygonInput read = read_polygon_input(text, hint);
    in.polygon = std::move(read.polygon);
    in.ring_names = std::move(read.ring_names);
    in.exact = std::move(read.exact);
  } catch (const InvalidInput& e) {
    throw InvalidInput(in.name + ": " + e.what());
  }
  return in;
}

PartsInput read_parts(const std::string& argument, std::string_view role) {
  const std::string who(role);
  const Loaded l = load_argument(argument, who);
  PartsInput in;
  in.name = who + " (" + l.where + ")";
  try {
    in.parts = read_parts_input(l.text, l.hint);
  } catch (const InvalidInput& e) {
    throw InvalidInput(in.name + ": " + e.what());
  }
  return in;
}

}  // namespace mk::cli
