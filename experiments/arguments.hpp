// mkbool-experiment's argument checks: every bad argument is a usage error, exit 2 on one
// line naming the argument and what it expects, found while parsing (issue 10).
// [MK89 §3.3] (the experiments' command)
// Preconditions: included by experiments/main.cpp only (CLI11 is its dependency).
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

#include "api/mkbool.hpp"

namespace mk::experiments::arguments {

namespace fs = std::filesystem;

constexpr int usage_exit = 2;

inline int usage_error(const std::string& message) {
  std::cerr << "mkbool-experiment: error: " << message << " (see mkbool-experiment --help)\n";
  return usage_exit;
}

// A check that runs on the argument's text before CLI11 converts it, so that "-5" never
// becomes 2^64 - 5 and the message says what is expected in words.
inline CLI::Validator whole_number(std::uint64_t min, std::uint64_t max, const std::string& what) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        std::uint64_t v = 0;
        const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits || r.ec != std::errc() || r.ptr != text.data() + text.size() || v < min || v > max) {
          return "expected " + what + ", got '" + text + "'";
        }
        return {};
      },
      "", "whole_number");
}

inline CLI::Validator positive_seconds() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0;
        const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
        if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !(v > 0) || !std::isfinite(v)) {
          return "expected a positive number of seconds, got '" + text + "'";
        }
        return {};
      },
      "", "positive_seconds");
}

// A check that a function accepts the text (it throws std::invalid_argument otherwise).
template <class F>
CLI::Validator accepted_by(F&& f, const char* name) {
  return CLI::Validator(
      [f](std::string& text) -> std::string {
        try {
          f(text);
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
        return {};
      },
      "", name);
}

inline void check_kernel(const std::string& k) {
  std::string known;
  for (const auto n : mk::kernel_names()) {
    if (n == k) return;
    known += (known.empty() ? "" : ", ") + std::string(n);
  }
  throw std::invalid_argument("unknown kernel '" + k + "' (built: " + known + ")");
}

// The operation names of the command; symdifference is a synonym of xor everywhere.
inline std::string operation_argument(const std::string& name) { return name == "symdifference" ? "xor" : name; }

// Whether DIR holds results*.csv files (what report and merge read).
inline bool has_results(const std::string& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("results", 0) == 0 && e.path().extension() == ".csv") return true;
  }
  return false;
}

}  // namespace mk::experiments::arguments
