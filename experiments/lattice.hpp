// Exact integer-lattice geometry for the degenerate generators: points, orientation,
// convex hulls, random convex and star polygons, and the lattice's exact symmetries.
// [MK89 §2.2] (simple polygons, vertex-complete pairs built from them)
// Preconditions: coordinates stay below 2^30 in magnitude, so every orientation fits in
// 64 bits and every point is exactly a double.
#pragma once

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/polygon.hpp"

namespace mk::experiments {

// Bounded retries for the random constructions: a generator that cannot build its case
// throws (the runner records invalid_input) instead of looping forever.
class Attempts {
 public:
  explicit Attempts(const char* what, int limit = 100000) : what_(what), limit_(limit) {}
  void next() {
    if (++count_ > limit_) throw std::runtime_error(std::string("gave up after ") + std::to_string(limit_) + " tries: " + what_);
  }

 private:
  const char* what_;
  int limit_;
  int count_ = 0;
};

struct IPoint {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend bool operator==(const IPoint&, const IPoint&) = default;
  friend IPoint operator+(IPoint a, IPoint b) { return {a.x + b.x, a.y + b.y}; }
  friend IPoint operator-(IPoint a, IPoint b) { return {a.x - b.x, a.y - b.y}; }
  friend IPoint operator*(std::int64_t s, IPoint a) { return {s * a.x, s * a.y}; }
};

using IRing = std::vector<IPoint>;

// Sign of (b - a) x (c - a): positive when c lies left of a -> b.
inline int orient(IPoint a, IPoint b, IPoint c) {
  const std::int64_t d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return (d > 0) - (d < 0);
}

// Twice the signed area (positive when counterclockwise).
std::int64_t twice_area(const IRing& r);

// Convex hull, counterclockwise, without collinear points; empty when the points are
// collinear (fewer than 3 hull vertices).
IRing convex_hull(std::vector<IPoint> points);

// A random convex polygon of `count` sample points (at least a triangle) in the box
// [lo, hi]^2 around `centre`.
IRing random_convex(std::mt19937_64& rng, IPoint centre, std::int64_t radius, int count);

// A random star-shaped polygon around (centre + 1/2, centre + 1/2) with vertices at integer
// distances in [rmin, rmax] from it: simple by construction (sorted by exact angle, one
// vertex per direction, every gap below pi). Retries until it succeeds.
IRing random_star(std::mt19937_64& rng, IPoint centre, int rmin, int rmax, int count);

// Whether q lies strictly inside the convex counterclockwise ring r.
bool is_strictly_inside_convex(const IRing& r, IPoint q);

// Whether q lies strictly inside the simple ring r (crossing parity; q not on r).
bool is_inside_ring(const IRing& r, IPoint q);
bool is_on_ring(const IRing& r, IPoint q);
// Whether closed segments ab and cd have a point in common.
bool segments_meet(IPoint a, IPoint b, IPoint c, IPoint d);
// Whether two rings have a point in common (crossing, touching or overlapping edges).
bool rings_meet(const IRing& r, const IRing& s);
// Whether ring `inner` lies strictly inside simple ring `outer` (no common point).
bool is_strictly_inside(const IRing& outer, const IRing& inner);

// A random point strictly on the left of a -> b within distance `reach` of `near`.
IPoint random_point_left_of(std::mt19937_64& rng, IPoint a, IPoint b, IPoint near, std::int64_t reach);

// The lattice's exact symmetries: one of the 8 rotations/reflections of the square, then a
// translation. Used to vary a configuration without breaking its degeneracy.
struct LatticeMap {
  int symmetry = 0;  // 0..7
  IPoint shift;
  IPoint operator()(IPoint p) const;
};
LatticeMap random_lattice_map(std::mt19937_64& rng, std::int64_t max_shift);
IRing apply(const LatticeMap& m, const IRing& r);

IRing scaled(const IRing& r, std::int64_t s);
IRing translated(const IRing& r, IPoint d);
IRing reversed(IRing r);
// The point reflection through c/2 (c given doubled, so half-integer centres stay exact).
IRing point_reflected(const IRing& r, IPoint twice_centre);
// Rotation by 90 degrees counterclockwise about p.
IRing rotated90(const IRing& r, IPoint p);
// The ring starting at its k-th vertex.
IRing shifted_start(const IRing& r, std::size_t k);

Ring to_ring(const IRing& r);
Polygon island(std::vector<IRing> rings);
Polygon hole_type(std::vector<IRing> rings);

std::int64_t uniform(std::mt19937_64& rng, std::int64_t lo, std::int64_t hi);

}  // namespace mk::experiments
