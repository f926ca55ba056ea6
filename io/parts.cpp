// Checking multi-part OGC input against its reading by nesting (see parts.hpp).
// [OGC06-103 §6.1.11] [MK89 §2.2]
// Preconditions: see parts.hpp.
#include "io/parts.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/error.hpp"
#include "core/ring_windings.hpp"
#include "io/ring_rules.hpp"
#include "io/text_util.hpp"

namespace mk {

namespace {

std::string point_text(const Point& p) {
  std::string s(1, '(');
  io_detail::append_double(s, p.x);
  s += ' ';
  io_detail::append_double(s, p.y);
  s += ')';
  return s;
}

std::string edge_text(const Point& from, const Point& to) {
  return "edge from " + point_text(from) + " to " + point_text(to);
}

// Where each ring of the flattened polygon came from.
struct RingOrigin {
  std::size_t part = 0;
  std::size_t index = 0;  // 0: the shell
};

// Two rings as the same cycle of points, whatever their start and direction.
bool same_ring(const Ring& a, const Ring& b) {
  if (a.size() != b.size() || a.empty()) return false;
  const std::size_t n = a.size();
  for (std::size_t start = 0; start < n; ++start) {
    if (!(b[start] == a[0])) continue;
    bool forward = true;
    bool backward = true;
    for (std::size_t i = 0; i < n && (forward || backward); ++i) {
      forward = forward && b[(start + i) % n] == a[i];
      backward = backward && b[(start + n - i) % n] == a[i];
    }
    if (forward || backward) return true;
  }
  return false;
}

class Describer {
 public:
  Describer(const MultiPolygon& mp, const PartNames& names, const std::vector<RingOrigin>& origins)
      : mp_(mp), names_(names), origins_(origins) {}

  std::string ring(int r) const {
    const RingOrigin& o = origins_[static_cast<std::size_t>(r)];
    return ring_name(names_, o.part, o.index);
  }
  std::string ring_with_role(int r) const {
    return ring(r) + (origins_[static_cast<std::size_t>(r)].index == 0 ? " (a shell)" : " (a hole)");
  }
  std::string part(int r) const { return names_.parts[origins_[static_cast<std::size_t>(r)].part]; }
  bool is_hole(int r) const { return origins_[static_cast<std::size_t>(r)].index > 0; }
  std::size_t part_index(int r) const { return origins_[static_cast<std::size_t>(r)].part; }

  // Whether the winding number is wrong all along the inside of ring r (oriented as OGC
  // reads it, the inside is on the left of a shell and on the right of a hole).
  bool inside_all_bad(const WindingViolation& v, int r) const {
    return v.all_bad.at(static_cast<std::size_t>(r))[is_hole(r) ? 1 : 0];
  }

  // Within one part: holes outside the shell, holes in holes, rings looping over themselves.
  std::string within_part(const WindingViolation& v) const {
    const std::string near = " (near the " + edge_text(v.from, v.to) + ")";
    std::vector<int> holes;  // the part's holes around the point
    int shell_winding = 0;
    for (const auto& [r, w] : v.winding_rings) {
      if (is_hole(r) && w < 0) {
        holes.push_back(r);
      } else if (!is_hole(r)) {
        shell_winding = w;
      }
    }

    if (v.winding < 0 && shell_winding == 0 && !holes.empty()) {
      // Named: a hole wholly outside if there is one, else the first one partly outside.
      const auto wholly = std::find_if(holes.begin(), holes.end(), [&](int h) { return inside_all_bad(v, h); });
      const int hole = wholly != holes.end() ? *wholly : holes[0];
      const bool outside = wholly != holes.end();
      return ring_with_role(hole) + (outside ? " lies outside its shell (" : " is partly outside its shell (") +
             ring(hole - static_cast<int>(origins_[static_cast<std::size_t>(hole)].index)) + ")" +
             (outside ? "" : near) + "; a hole must lie inside its polygon's shell";
    }
    if (v.winding < 0 && shell_winding > 0 && holes.size() >= 2) {
      // The inner one, if one lies wholly inside the other.
      const auto inner = std::find_if(holes.begin(), holes.end(), [&](int h) { return inside_all_bad(v, h); });
      const int one = inner != holes.end() ? *inner : holes[0];
      const int other = holes[0] == one ? holes[1] : holes[0];
      const auto& holes_of = mp_[part_index(one)].holes;
      const auto hole_ring = [&](int r) -> const Ring& {
        return holes_of[origins_[static_cast<std::size_t>(r)].index - 1];
      };
      std::string what;
      if (same_ring(hole_ring(one), hole_ring(other))) {
        what = ring(std::max(one, other)) + " repeats " + ring(std::min(one, other)) + " (both holes)";
      } else if (inner != holes.end()) {
        what = ring_with_role(one) + " lies inside " + ring_with_role(other);
      } else {
        what = ring(std::min(one, other)) + " and " + ring(std::max(one, other)) + " (holes) overlap" + near;
      }
      return what + "; the holes of a polygon must not overlap";
    }
    return ring_with_role(v.ring) +
           (v.winding > 1 ? " covers some of its area twice" : " runs the wrong way around part of its area") + near +
           ": a ring that touches itself must not loop over or against itself";
  }

  // Between parts: a part inside, repeating or overlapping another.
  std::string between_parts(const WindingViolation& v) const {
    std::optional<int> other;
    for (const auto& [r, w] : v.winding_rings) {
      if (w > 0 && part_index(r) != part_index(v.ring) && !is_hole(r)) {
        other = r;
        break;
      }
    }
    const std::string rule = "; the parts of a multi-part polygon must not overlap (read by nesting, the overlap "
                             "would become a hole: merge the parts first)";
    if (!other) {
      return part(v.ring) + " overlaps other parts (beside its " + edge_text(v.from, v.to) + ")" + rule;
    }
    const std::size_t p = part_index(*other);
    const std::size_t q = part_index(v.ring);
    if (same_ring(mp_[p].shell, mp_[q].shell)) {
      return names_.parts[std::max(p, q)] + " repeats " + names_.parts[std::min(p, q)] +
             " (their shells are the same ring)" + rule;
    }
    const int shell_p = *other - static_cast<int>(origins_[static_cast<std::size_t>(*other)].index);
    const int shell_q = v.ring - static_cast<int>(origins_[static_cast<std::size_t>(v.ring)].index);
    if (inside_all_bad(v, shell_q)) return names_.parts[q] + " lies inside " + names_.parts[p] + rule;
    if (inside_all_bad(v, shell_p)) return names_.parts[p] + " lies inside " + names_.parts[q] + rule;
    return names_.parts[std::min(p, q)] + " and " + names_.parts[std::max(p, q)] + " overlap (beside the " +
           edge_text(v.from, v.to) + " of " + ring(v.ring) + ")" + rule;
  }

 private:
  const MultiPolygon& mp_;
  const PartNames& names_;
  const std::vector<RingOrigin>& origins_;
};

}  // namespace

std::string describe_crossing(const CrossingEdges& e, const Polygon& polygon, const std::vector<std::string>& ring_names) {
  const auto edge = [&](const RingEdge& x) {
    const Ring& r = polygon.rings.at(static_cast<std::size_t>(x.ring));
    return edge_text(r.at(static_cast<std::size_t>(x.from)), r.at(static_cast<std::size_t>(x.to)));
  };
  const auto ring = [&](int r) { return ring_names.at(static_cast<std::size_t>(r)); };
  if (e.first().ring == e.second().ring) {
    return ring(e.first().ring) + ": its " + edge(e.first()) + " crosses its " + edge(e.second()) +
           "; the edges of a polygon may touch but must not cross";
  }
  return "the " + edge(e.first()) + " of " + ring(e.first().ring) + " crosses the " + edge(e.second()) + " of " +
         ring(e.second().ring) + "; the edges of a polygon may touch but must not cross";
}

std::string ring_name(const PartNames& names, std::size_t part, std::size_t k) {
  const std::string& p = names.parts.at(part);
  return names.json_paths ? p + "[" + std::to_string(k) + "]" : p + ", ring " + std::to_string(k);
}

Polygon to_checked_polygon(const MultiPolygon& mp, const PartNames& names) {
  Polygon flat;
  std::vector<RingOrigin> origins;
  std::vector<int> group;
  std::vector<bool> reversed;
  for (std::size_t p = 0; p < mp.size(); ++p) {
    for (std::size_t k = 0; k <= mp[p].holes.size(); ++k) {
      const Ring& ring = k == 0 ? mp[p].shell : mp[p].holes[k - 1];
      flat.rings.push_back(ring);
      origins.push_back({p, k});
      group.push_back(static_cast<int>(p));
      // As OGC reads them: shells counterclockwise, holes clockwise, whatever the text says.
      const int orientation = io_detail::ring_orientation(ring);
      reversed.push_back(k == 0 ? orientation < 0 : orientation > 0);
    }
  }
  if (flat.rings.empty()) return flat;
  const Describer describe(mp, names, origins);
  std::optional<WindingViolation> v;
  try {
    v = find_winding_violation<ExactKernel>(flat, group, reversed);
  } catch (const CrossingEdges& e) {
    std::vector<std::string> ring_names;
    for (const RingOrigin& o : origins) ring_names.push_back(ring_name(names, o.part, o.index));
    throw InvalidInput(describe_crossing(e, flat, ring_names));
  }
  if (v) throw InvalidInput(v->within_group ? describe.within_part(*v) : describe.between_parts(*v));
  return flat;
}

}  // namespace mk
