// Order of vertices along a segment for kernels whose vertices are explicit points:
// lexicographic order is monotone along any segment. [MK89 §3.1 step 3] (insertion in order)
// Preconditions: both vertices lie on the segment s -> d (up to the kernel's rounding).
#pragma once

#include "kernel/kernel.hpp"

namespace mk {

template <class K>
Sign compare_along_lexicographic(const typename K::Point& s, const typename K::Point& d,
                                 const typename K::Vertex& u, const typename K::Vertex& v) {
  const Sign c = K::compare_vertices(u, v);
  return K::compare_x(s, d) == Sign::positive || (K::compare_x(s, d) == Sign::zero && K::compare_y(s, d) == Sign::positive) ? -c : c;
}

}  // namespace mk
