// Helpers for the io tests: checking that an input is rejected with a given message.
// [OGC06-103 §7] [RFC7946]
// Preconditions: none.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "core/error.hpp"

namespace mk::test {

// Success when f throws mk::InvalidInput whose message contains `fragment`; the failure
// shows the actual message, so an expectation can be corrected from the log.
template <class F>
::testing::AssertionResult rejects(F&& f, std::string_view fragment) {
  try {
    f();
  } catch (const InvalidInput& e) {
    const std::string message = e.what();
    if (message.find(fragment) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "message \"" << message << "\" does not contain \"" << fragment << "\"";
  }
  return ::testing::AssertionFailure() << "no mk::InvalidInput thrown";
}

}  // namespace mk::test
