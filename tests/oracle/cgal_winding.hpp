// An independent exact reference for fill rules: CGAL's Arrangement_2 over Epeck of every
// input segment of every operand, the winding number of each face per operand found by
// walking from the unbounded face across edges, and the exact area and region of the
// bounded faces a predicate over those winding numbers selects.
// [BRIEF §1, extended by issue 13] (an input's region under a fill rule)
// Preconditions: rings are closed (the last point joins the first), have any number of
// points, and may cross, overlap and touch themselves and each other; coordinates are
// rationals small enough for Epeck (cgal_reference.hpp: below about 2^340).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tests/oracle/membership.hpp"

namespace mk::oracle {

class WindingArrangement {
 public:
  // One entry per operand: its rings, each in the direction given.
  explicit WindingArrangement(const std::vector<std::vector<QRing>>& operands);
  ~WindingArrangement();
  WindingArrangement(const WindingArrangement&) = delete;
  WindingArrangement& operator=(const WindingArrangement&) = delete;

  // Bounded faces of the arrangement, and each one's winding numbers (one per operand).
  std::size_t face_count() const;
  const std::vector<int>& windings(std::size_t face) const;
  // Empty when every edge crossed twice by the walk (once from each side, or an antenna with
  // the same face on both sides) gave the same winding numbers; else what disagreed (a bug
  // of this reference, never of the code under test).
  const std::string& inconsistency() const;

  using Selection = std::vector<bool>;  // per bounded face
  Selection select(const std::function<bool(const std::vector<int>&)>& in) const;
  // The exact area of the selected faces (each face's boundary cycles by the shoelace sum).
  Q area(const Selection& s) const;
  // The selected faces as a region of the paper's model: every boundary cycle of every
  // selected face as a ring (parity of the cycles gives the union of the faces' closures).
  Region region(const Selection& s) const;
  // The boundary of the selected faces as directed edges, each with a selected face on its
  // left and an unselected one (or the unbounded face) on its right.
  std::vector<std::pair<QPoint, QPoint>> boundary(const Selection& s) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Where the 1-chains of the directed edges x and of the closed rings y differ (the first
// line and position where their signed multiplicities differ), empty when they are equal.
// Two regions whose oriented boundaries (region on the left) are equal chains are equal:
// a region's indicator is the winding number of its boundary, so an empty answer for
// a result's boundary and its rings is an empty symmetric difference.
std::string chain_difference(const std::vector<std::pair<QPoint, QPoint>>& x, const std::vector<QRing>& y);

// The exact sign of a ring's signed area (positive: counterclockwise), for orienting the
// shells and holes of the `union` rule independently of api/fill.cpp.
int orientation_sign(const QRing& r);

}  // namespace mk::oracle
