// Test oracle: exact point membership in polygons of the paper's model and in Boolean
// results, written for the tests alone: crossing parity and angular sectors over GMP
// rationals, sharing no code and no truth table with core/ (only its data types).
// [BRIEF §1] (semantics: closed regions, regular and closed-set operations) [MK89 §2.2]
// Preconditions: rings do not cross (they may touch, share vertices and edges); a region's
// rings are closed (the last point joins the first), of any length (1: a point, 2: a
// two-sided segment).
#pragma once

#include <gmpxx.h>

#include <random>
#include <string>
#include <vector>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/polygon.hpp"

namespace mk::oracle {

using Q = mpq_class;
using QPoint = RationalPoint;
using QRing = std::vector<QPoint>;

// A closed point set of the paper's model [BRIEF §1]: FAR is the set of points enclosed by
// an odd number of rings of 3+ points (the inclusion forest's parity); the region is FAR
// plus every ring's points, or, when `complement` (a hole-type polygon, an unbounded
// result), the closure of FAR's complement plus every ring's points.
struct Region {
  std::vector<QRing> rings;
  bool complement = false;
};

Region region_of(const Polygon& p);
Region region_of(const BasicPolygon<QPoint>& p);

// Where a point lies in a region: in its interior, in it but not in its interior (boundary
// of the area part, a dangling edge, an isolated point), or outside it.
enum class Location { outside, boundary, inside };
const char* location_name(Location l);

// The neighbourhood of a point p in the plane cut by the rings of several regions: whether
// p is on each region's rings, and one point in each open sector around p between
// consecutive ring directions at p (one sector, the whole turn, when p is on no ring),
// close enough to p that no ring separates it from p's sector.
struct Neighbourhood {
  QPoint p;
  std::vector<bool> on_rings;      // per region
  std::vector<QPoint> sector_points;
};
Neighbourhood neighbourhood(const QPoint& p, const std::vector<const Region*>& regions);

// A point of the open face just left of segment a -> b at its midpoint (no ring of the
// regions passes between them).
QPoint point_left_of(const QPoint& a, const QPoint& b, const std::vector<const Region*>& regions);

// Whether q, on no ring of r, lies in r's region.
bool face_is_in(const Region& r, const QPoint& q);
// The location of the neighbourhood's centre in region i of the neighbourhood.
Location locate(const Neighbourhood& n, const std::vector<const Region*>& regions, std::size_t i);
// The location of p in r (a neighbourhood of its own).
Location locate(const Region& r, const QPoint& p);

// The set operations by their definitions [BRIEF §1], written here from the operation alone:
// on open faces, and as closed sets from membership in A, int(A), B, int(B).
bool face_in_result(Operation op, bool in_a, bool in_b);
bool in_closed_result(Operation op, bool in_a, bool int_a, bool in_b, bool int_b);

// What the operation says p's location in the result must be: for the regular operation
// from the faces around p (all in: inside; some: boundary; none: outside), for the
// closed-set one from the membership of p in A, int(A), B and int(B) (inside or outside;
// the closed set's interior is not decided point by point, so "boundary" never comes
// back: compare membership, location != outside).
Location expected_location(Operation op, bool regular, const Region& a, const Region& b, const QPoint& p);

// Sample points for a pair of inputs and a result: every vertex, every crossing of an edge
// of A with an edge of B, the midpoint of every piece of an input edge between consecutive
// points of A and B on it (so points on both boundaries where edges overlap), every result
// edge's midpoint, and `random_count` random points of the inputs' bounding box and on
// random input edges.
std::vector<QPoint> sample_points(const Region& a, const Region& b, const Region& result, std::mt19937_64& rng,
                                  int random_count);

// How many sample points were checked, and how many of them lie on both A's and B's rings
// (where bugs live: shared vertices, overlapping edges, vertices on edges, crossings).
struct SampleCounts {
  long points = 0;
  long on_both_boundaries = 0;
};

// The first sample point where the result's location contradicts the operation's
// definition, described; empty when every sample agrees.
std::string first_contradiction(Operation op, bool regular, const Region& a, const Region& b,
                                const Region& result, const std::vector<QPoint>& samples,
                                SampleCounts* counts = nullptr);

std::string show(const QPoint& p);

// Whether p lies on the closed segment ab.
bool is_on_segment(const QPoint& a, const QPoint& b, const QPoint& p);

}  // namespace mk::oracle
