// Integer shapes on a small grid for the test families (families.hpp): stars, convex parts,
// cell sets and their boundaries, holes touching shells, vertices on edges, and the check
// that keeps every shape inside mkbool's model (rings may touch, share edges and nest, but
// never cross, not even through a point they share).
// [BRIEF §1] (the polygon model) [MK89 §2.2]
// Preconditions: coordinates small enough for exact products in long long.
#pragma once

#include <random>
#include <set>
#include <utility>
#include <vector>

namespace mk::oracle::grid {

using Int = long long;
struct IP {
  Int x, y;
  friend bool operator==(const IP&, const IP&) = default;
  friend auto operator<=>(const IP&, const IP&) = default;
};
using IRing = std::vector<IP>;
struct IPoly {
  std::vector<IRing> rings;
  bool hole = false;
};

using Rng = std::mt19937_64;
Int uniform(Rng& rng, Int lo, Int hi);
bool chance(Rng& rng, int one_in);

// Outside mkbool's model: a proper crossing, or two rings crossing through a contact.
bool is_outside_the_model(const IPoly& p);
bool is_same_set(IRing a, IRing b);

IRing convex_hull(std::vector<IP> pts);
IRing random_convex(Rng& rng, Int x0, Int y0, Int x1, Int y1, int points);
IRing random_star(Rng& rng, Int cx, Int cy, int rmin, int rmax, int n);

using Cells = std::set<std::pair<Int, Int>>;
Cells random_cells(Rng& rng, Int w, Int h, int percent);
IPoly cells_as_parts(const Cells& cells, Int s);
IPoly cells_as_boundary(const Cells& cells, Int s, bool through, Rng& rng);

IPoly grid_star(Rng& rng, Int cx, Int cy);
IPoly holes_touching(Rng& rng);
IPoly multi_part(Rng& rng);
std::pair<IPoly, IPoly> vertex_on_edge(Rng& rng);
IPoly fan(Rng& rng, IP apex, Int r);
std::pair<IPoly, IPoly> fans(Rng& rng);

}  // namespace mk::oracle::grid
