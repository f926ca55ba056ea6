// Test oracle for fill rules: the exact winding number of rings at a point, by the signed
// crossings of a horizontal ray over GMP rationals, written for the tests alone (no code of
// core/ or predicates/), and the regions of the four fill rules from it.
// [BRIEF §1, extended by issue 13] (an input's region under a fill rule)
// Preconditions: the point lies on no ring (is_on_any_ring says so); rings are closed (the
// last point joins the first) and may cross themselves and each other.
#pragma once

#include <vector>

#include "tests/oracle/membership.hpp"

namespace mk::oracle {

// The winding number of the rings, each in its given direction, around q.
int winding_number(const std::vector<QRing>& rings, const QPoint& q);

// Whether q lies on an edge (or is a vertex) of one of the rings.
bool is_on_any_ring(const std::vector<QRing>& rings, const QPoint& q);

// Clipper's four fill rules, written from their definitions.
enum class Rule { evenodd, nonzero, positive, negative };
bool rule_accepts(Rule rule, int winding);
const char* rule_name(Rule rule);

}  // namespace mk::oracle
