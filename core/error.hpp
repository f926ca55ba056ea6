// Errors for input outside the domain and for failures of inexact kernels.
// [MK89 §3.3] (orientable inputs are repaired; crossing edges are rejected)
// Preconditions: none.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/polygon.hpp"

namespace mk {

// Input that is malformed or outside the vertex-complete domain. The message names what
// and where (polygon, ring, vertex index; or line and column for text formats).
class InvalidInput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One edge of an input ring, by the ring's index and the indices of its end vertices in the
// ring as given to the library.
struct RingEdge {
  int ring = -1;
  int from = -1;
  int to = -1;
};

// Two edges of one input polygon cross at a point inside both [MK89 §3.3: touching edges
// are repaired, crossing ones cannot be]. Carries the edges so that callers which know more
// (coordinates, how the user named the rings) can say it in their words.
class CrossingEdges : public InvalidInput {
 public:
  CrossingEdges(int polygon, RingEdge first, RingEdge second, const std::string& message)
      : InvalidInput(message), polygon_(polygon), first_(first), second_(second) {}
  int polygon() const { return polygon_; }  // 0 for A, 1 for B
  const RingEdge& first() const { return first_; }
  const RingEdge& second() const { return second_; }

 private:
  int polygon_;
  RingEdge first_;
  RingEdge second_;
};

// A kernel whose predicates are not exact produced an inconsistent arrangement (for
// example a vertex ring that does not close). Never raised by exact kernels on valid input.
class KernelFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Rejects NaN and infinite coordinates, naming the polygon ("A" or "B"), ring and vertex.
inline void validate_coordinates(const Polygon& p, const char* name) {
  for (std::size_t r = 0; r < p.rings.size(); ++r) {
    for (std::size_t v = 0; v < p.rings[r].size(); ++v) {
      const Point& q = p.rings[r][v];
      if (!std::isfinite(q.x) || !std::isfinite(q.y)) {
        throw InvalidInput(std::string("polygon ") + name + ", ring " + std::to_string(r) +
                           ", vertex " + std::to_string(v) + ": coordinate is not finite");
      }
    }
  }
}

}  // namespace mk
