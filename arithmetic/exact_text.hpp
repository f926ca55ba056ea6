// Exact numbers written as text: integers "p", fractions "p/q" and decimals ("0.1",
// "-2.5e-3"), each taken as the rational number it writes (0.1 is 1/10, not the double
// nearest to it). [BRIEF §6a] (exact in, exact out)
// Preconditions: none; text that is not such a number gives std::nullopt.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace mk {

namespace exact_text_detail {
inline bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (const char c : s) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}
}  // namespace exact_text_detail

// The exact value of `text`, or nullopt (also for a zero denominator, and for more than
// `max_chars` characters or a decimal exponent beyond +-`max_exponent`, which would make
// numbers too large to be meant).
inline std::optional<mpq_class> parse_exact_number(std::string_view text, std::size_t max_chars = 100000,
                                                   long max_exponent = 100000) {
  using exact_text_detail::all_digits;
  if (text.size() > max_chars) return std::nullopt;
  bool negative = false;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
    negative = text[0] == '-';
    text.remove_prefix(1);
  }
  mpq_class v;
  const std::size_t slash = text.find('/');
  if (slash != std::string_view::npos) {
    const std::string_view p = text.substr(0, slash), q = text.substr(slash + 1);
    if (!all_digits(p) || !all_digits(q)) return std::nullopt;
    mpz_class den(std::string(q), 10);
    if (den == 0) return std::nullopt;
    v = mpq_class(mpz_class(std::string(p), 10), den);
    v.canonicalize();
  } else {
    std::string_view mantissa = text;
    long power = 0;
    const std::size_t e = text.find_first_of("eE");
    if (e != std::string_view::npos) {
      mantissa = text.substr(0, e);
      std::string_view exponent = text.substr(e + 1);
      bool exp_negative = false;
      if (!exponent.empty() && (exponent[0] == '-' || exponent[0] == '+')) {
        exp_negative = exponent[0] == '-';
        exponent.remove_prefix(1);
      }
      if (!all_digits(exponent) || exponent.size() > 9) return std::nullopt;
      power = std::stol(std::string(exponent));
      if (power > max_exponent) return std::nullopt;
      if (exp_negative) power = -power;
    }
    const std::size_t dot = mantissa.find('.');
    const std::string_view whole = mantissa.substr(0, dot);
    const std::string_view fraction = dot == std::string_view::npos ? std::string_view() : mantissa.substr(dot + 1);
    if ((!whole.empty() && !all_digits(whole)) || (!fraction.empty() && !all_digits(fraction)) ||
        (whole.empty() && fraction.empty())) {
      return std::nullopt;
    }
    power -= static_cast<long>(fraction.size());
    const mpz_class digits(std::string(whole) + std::string(fraction), 10);
    mpz_class scale;
    mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(power < 0 ? -power : power));
    v = power < 0 ? mpq_class(digits, scale) : mpq_class(digits * scale);
    v.canonicalize();
  }
  if (negative) v = -v;
  return v;
}

}  // namespace mk
