// The exit codes of the mkbool command and the error kinds that map to them (issue 3).
// [MK89 §3.2] (procedure polygonoperation: the command is its shell front end)
// Preconditions: none.
#pragma once

#include <stdexcept>

namespace mk::cli {

// Documented in docs/usage.md; scripts branch on them, so they never change meaning.
enum class ExitCode : int {
  success = 0,
  failure = 1,        // anything else: unwritable output, unbounded result as WKT, kernel failure
  usage = 2,          // the command line itself is wrong
  invalid_input = 3,  // an input is malformed or outside the domain (mk::InvalidInput)
  invalid_output = 4, // --rounding nearest (or an inexact kernel) wrote polygons that are not
                      // valid once rounded; the output is written and a warning printed
};

// The output was written but is not a valid polygon (exit code 4, after the output).
class InvalidOutput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A command line that parsed but asks for something impossible (two standard inputs).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A valid result that cannot be written as asked (an unbounded result as WKT or GeoJSON),
// or an output that cannot be written at all.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mk::cli
