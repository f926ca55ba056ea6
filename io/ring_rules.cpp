// Ring rules shared by the readers and writers (see ring_rules.hpp).
// [OGC06-103 §6.1.7] [RFC7946 §3.1.6] [Sh97]
// Preconditions: coordinates are finite.
#include "io/ring_rules.hpp"

#include <gmpxx.h>

#include <cstddef>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "io/text_util.hpp"

namespace mk::io_detail {

namespace {

std::string point_text(const Point& p) {
  std::string s(1, '(');
  append_double(s, p.x);
  s += ' ';
  append_double(s, p.y);
  s += ')';
  return s;
}

// True when the ring has at least three pairwise distinct points; one pass, no sorting.
bool has_three_distinct_points(const Ring& ring) {
  if (ring.empty()) return false;
  const Point a = ring.front();
  std::size_t i = 1;
  while (i < ring.size() && ring[i] == a) ++i;
  if (i == ring.size()) return false;
  const Point b = ring[i];
  for (; i < ring.size(); ++i) {
    if (!(ring[i] == a) && !(ring[i] == b)) return true;
  }
  return false;
}

bool lexicographically_less(const Point& p, const Point& q) {
  return p.x < q.x || (p.x == q.x && p.y < q.y);
}

int sign_of(const mpq_class& v) { return sgn(v); }

// Exact orient2d(a, b, c) on doubles, by Shewchuk's adaptive stages [Sh97]: a written result
// of many small rings asks it once per ring, and rationals made it cost more than the text.
int exact_orientation(const Point& a, const Point& b, const Point& c) {
  return static_cast<int>(ExactKernel::orient2d(a, b, c));
}

// Exact twice-area relative to the first vertex: the fallback for rings whose extreme
// vertex is degenerate (spikes, collinear runs through the extreme point).
int exact_area_sign(const Ring& ring) {
  const mpq_class ox(ring[0].x), oy(ring[0].y);
  mpq_class sum = 0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    const mpq_class ux = mpq_class(ring[i].x) - ox, uy = mpq_class(ring[i].y) - oy;
    const mpq_class vx = mpq_class(ring[i + 1].x) - ox, vy = mpq_class(ring[i + 1].y) - oy;
    sum += ux * vy - uy * vx;
  }
  return sign_of(sum);
}

}  // namespace

OgcRingProblem check_ogc_ring(const Ring& closed) {
  if (closed.size() < 4) return OgcRingProblem::too_few_coordinates;
  if (!(closed.front() == closed.back())) return OgcRingProblem::not_closed;
  if (!has_three_distinct_points(closed)) return OgcRingProblem::too_few_distinct_points;
  return OgcRingProblem::none;
}

std::string describe_ogc_ring_problem(const Ring& closed, OgcRingProblem problem) {
  switch (problem) {
    case OgcRingProblem::none: return "ring is valid";
    case OgcRingProblem::too_few_coordinates:
      return "ring has " + std::to_string(closed.size()) +
             " coordinates; a closed ring needs at least 4 (3 distinct points and the "
             "closing point)";
    case OgcRingProblem::not_closed:
      return "ring is not closed: last vertex " + point_text(closed.back()) +
             " differs from first vertex " + point_text(closed.front());
    case OgcRingProblem::too_few_distinct_points:
      return "ring has fewer than 3 distinct points; a ring needs at least 3";
  }
  return "ring is invalid";
}

void remove_repeated_vertices(Ring& ring) { remove_repeated_points(ring); }

int ring_orientation(const Ring& ring) {
  if (ring.size() < 3) return 0;
  std::size_t low = 0;
  for (std::size_t i = 1; i < ring.size(); ++i) {
    if (lexicographically_less(ring[i], ring[low])) low = i;
  }
  // A ring that passes through its extreme vertex twice (touching itself there) turns there
  // once per pass, and the turns may differ: only its whole area decides.
  const std::size_t n = ring.size();
  std::size_t visits = 0;  // runs of repeated copies count once
  for (std::size_t i = 0; i < n; ++i) visits += ring[i] == ring[low] && !(ring[(i + n - 1) % n] == ring[low]);
  if (visits > 1) return exact_area_sign(ring);
  // Neighbours equal to the extreme vertex (repeated vertices) are skipped.
  std::size_t prev = (low + n - 1) % n;
  while (prev != low && ring[prev] == ring[low]) prev = (prev + n - 1) % n;
  std::size_t next = (low + 1) % n;
  while (next != low && ring[next] == ring[low]) next = (next + 1) % n;
  if (prev != low && next != low) {
    const int s = exact_orientation(ring[prev], ring[low], ring[next]);
    if (s != 0) return s;
  }
  return exact_area_sign(ring);
}

}  // namespace mk::io_detail
