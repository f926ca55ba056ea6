// The input point: two doubles. Every kernel is built from these.
// [MK89 §2.2] (vertices of the rings)
// Preconditions: none here; finiteness is checked where input enters (core/error.hpp).
#pragma once

namespace mk {

struct Point {
  double x = 0;
  double y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

}  // namespace mk
