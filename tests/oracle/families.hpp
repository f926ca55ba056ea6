// Random input pairs for the differential and membership tests, in families that stress the
// algorithm rather than the arithmetic: shared vertices and edges, collinear overlaps,
// vertices on edges, identical and reversed rings, holes touching shells and each other at
// vertices, multi-part inputs, rings touching themselves at repeated vertices, fans of dozens
// of parts meeting at one vertex. Each is made
// on a small integer grid and then moved off it exactly: a rotation by a Pythagorean angle
// (an integer matrix, so every degeneracy survives), a scaling by 2^k for k anywhere in the
// double exponent range (subnormal to 2^1000), a translation, and a shuffle of ring starts,
// directions and order.
// [BRIEF §1] (the polygon model) [BRIEF §5] (generator names) [MK89 §2.2]
// Preconditions: none; every pair is in mkbool's input domain (rings of one polygon do not
// cross; holes touch shells only at points).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/polygon.hpp"

namespace mk::oracle {

struct GeneratedPair {
  std::string family;     // the generator's name (as in experiments/)
  std::string transform;  // how the grid configuration was moved, e.g. "rot(3,4,5) 2^-1000"
  Polygon a;
  Polygon b;
};

// The families, in the order `random_pair` cycles through them.
const std::vector<std::string>& family_names();

// A pair of family `family_names()[index % size]`, moved by a random exact transform.
GeneratedPair random_pair(std::size_t index, std::mt19937_64& rng);

// A polygon on one line, for failure messages (doubles in shortest round-trip form).
std::string describe(const Polygon& p);

}  // namespace mk::oracle
