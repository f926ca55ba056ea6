// Peer verdicts against the exact reference, the rounding bound, and the independent point
// check for disagreements between exact results. [MK89 §3.3] [BRIEF §5]
// Preconditions: see peer_verdict.hpp.
#include "experiments/peer_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/boolean_op.hpp"
#include "experiments/ogc.hpp"

namespace mk::experiments {

namespace {

using Rings = std::vector<std::vector<RationalPoint>>;

enum class Location { inside, boundary, outside };

// Crossing parity of p against every ring (the nesting-parity region), exact; rays to +x.
Location locate(const Rings& rings, const RationalPoint& p) {
  bool in = false;
  for (const auto& r : rings) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      const auto& a = r[i];
      const auto& b = r[(i + 1) % r.size()];
      const mpq_class cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
      if (cross == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
          p.y <= std::max(a.y, b.y)) {
        return Location::boundary;
      }
      if ((a.y > p.y) != (b.y > p.y) && (b.y > a.y ? cross > 0 : cross < 0)) in = !in;
    }
  }
  return in ? Location::inside : Location::outside;
}

Rings rings_of(const Polygon& p) {
  Rings out;
  for (const auto& r : p.rings) {
    out.emplace_back();
    for (const auto& v : r) out.back().push_back(RationalKernel::point(v));
  }
  return out;
}

Rings rings_of(const std::vector<ExactCycle>& cycles) {
  Rings out;
  for (const auto& c : cycles) {
    if (c.vertices.size() >= 3) out.push_back(c.vertices);
  }
  return out;
}

// Membership of a point not on any boundary; `complement` for hole-type or unbounded sets.
std::optional<bool> is_in(const Rings& rings, bool complement, const RationalPoint& p) {
  const Location l = locate(rings, p);
  if (l == Location::boundary) return std::nullopt;
  return (l == Location::inside) != complement;
}

// The set operations on memberships, written here rather than taken from the core's
// selection tables, so that the point check stays independent of them. [BRIEF §1]
bool in_result(Operation op, bool in_a, bool in_b) {
  switch (op) {
    case Operation::intersection: return in_a && in_b;
    case Operation::union_: return in_a || in_b;
    case Operation::difference: return in_a && !in_b;
    case Operation::symmetric_difference: return in_a != in_b;
  }
  return false;
}

std::string yes_no(bool b) { return b ? "inside" : "outside"; }

}  // namespace

double input_resolution(const Polygon& a, const Polygon& b) {
  double m = 0;
  for (const Polygon* p : {&a, &b}) {
    for (const auto& r : p->rings) {
      for (const Point& q : r) m = std::max({m, std::abs(q.x), std::abs(q.y)});
    }
  }
  return std::ldexp(m, -50);
}

double perimeter(const std::vector<ExactCycle>& cycles) {
  double total = 0;
  for (const auto& c : cycles) {
    if (c.vertices.size() < 3) continue;
    for (std::size_t i = 0; i < c.vertices.size(); ++i) {
      const auto& p = c.vertices[i];
      const auto& q = c.vertices[(i + 1) % c.vertices.size()];
      total += std::hypot(RationalKernel::to_nearest(mpq_class(q.x - p.x)), RationalKernel::to_nearest(mpq_class(q.y - p.y)));
    }
  }
  return total;
}

double rounding_bound(double delta, double perimeter_exact, double perimeter_result) {
  return 2 * delta * (perimeter_exact + perimeter_result);
}

std::vector<ExactCycle> peer_cycles(const PeerOutput& output) {
  std::vector<ExactCycle> out;
  const auto add = [&](std::vector<RationalPoint> ring, bool hole) {
    ExactCycle c{hole ? PolygonType::hole : PolygonType::island, {}};
    for (auto& v : ring) {
      if (c.vertices.empty() || !(c.vertices.back() == v)) c.vertices.push_back(std::move(v));
    }
    while (c.vertices.size() > 1 && c.vertices.back() == c.vertices.front()) c.vertices.pop_back();
    out.push_back(std::move(c));
  };
  if (output.is_exact) {
    for (const auto& polygon : output.exact_rings) {
      for (std::size_t i = 0; i < polygon.size(); ++i) add(polygon[i], i > 0);
    }
    return out;
  }
  const auto exact = [](const Ring& r) {
    std::vector<RationalPoint> e;
    for (const Point& p : r) e.push_back(RationalKernel::point(p));
    return e;
  };
  for (const OgcPolygon& p : output.polygons) {
    add(exact(p.shell), false);
    for (const Ring& h : p.holes) add(exact(h), true);
  }
  return out;
}

PeerAssessment assess_peer(const PeerOutput& output, const ExactResult* ref, double delta) {
  PeerAssessment pa;
  Assessment& as = pa.assessment;
  as.note = output.note;
  const auto add_note = [&](const std::string& s) { as.note += (as.note.empty() ? "" : "; ") + s; };
  bool finite = true;
  for (const OgcPolygon& p : output.polygons) {
    for (const Ring* r : {&p.shell}) {
      for (const Point& q : *r) finite = finite && std::isfinite(q.x) && std::isfinite(q.y);
    }
    for (const Ring& h : p.holes) {
      for (const Point& q : h) finite = finite && std::isfinite(q.x) && std::isfinite(q.y);
    }
  }
  if (!finite) {
    as.verdict = Verdict::invalid_output;
    add_note("a coordinate is not finite");
    pa.exact_valid = false;
    return pa;
  }
  if (!output.is_exact) {
    // CGAL's exact result is valid by construction (polygons with holes of its arrangement);
    // the others are checked as the user receives them.
    std::string why_exact, why_geos;
    pa.exact_valid = is_valid_ogc_exact(output.polygons, &why_exact);
    pa.geos_valid = geos_is_valid(output.polygons, &why_geos);
    if (!*pa.exact_valid) add_note("exact check: " + why_exact);
    if (pa.geos_valid == false) add_note("GEOS isValid: " + why_geos);
  }
  const bool invalid = pa.exact_valid == false || pa.geos_valid == false;
  if (ref == nullptr) {
    as.verdict = invalid ? Verdict::invalid_output : Verdict::unjudged;
    return pa;
  }
  const std::vector<ExactCycle> cycles = peer_cycles(output);
  if (ref->cycles.size() + cycles.size() > symdiff_polygon_limit) {
    as.verdict = invalid ? Verdict::invalid_output : Verdict::unjudged;
    add_note("area error not measured (" + std::to_string(ref->cycles.size() + cycles.size()) + " result polygons)");
    return pa;
  }
  pa.bound = output.is_exact ? 0.0 : rounding_bound(std::max(delta, output.grid), perimeter(ref->cycles), perimeter(cycles));
  const auto sd = symmetric_difference_area(cycles, output.unbounded, ref->cycles, ref->unbounded);
  if (!sd) {
    as.verdict = Verdict::invalid_output;
    add_note("the result's rings cross: no region to compare");
    return pa;
  }
  // The identity holds for valid K only: an invalid output's signed ring areas (overlapping
  // parts, say) are not its region's area, so it proves nothing about the reference there.
  if (sd->consistent == false && !invalid) {
    add_note("[reference inconsistency] area(K xor R) != area(K) + area(R) - 2 area(K and R)");
  }
  const bool same_area = output.unbounded == ref->unbounded && (ref->unbounded || typed_area(cycles) == ref->area);
  if (sd->infinite) {
    as.symdiff_area = as.area_error = std::numeric_limits<double>::infinity();
    as.verdict = Verdict::wrong;
    add_note(output.unbounded ? "unbounded, exact result bounded" : "bounded, exact result unbounded");
  } else {
    as.symdiff_area = RationalKernel::to_nearest(sd->area);
    const mpq_class base = ref->unbounded ? mpq_class(0) : mpq_class(abs(ref->area));
    as.area_error = RationalKernel::to_nearest(base == 0 ? sd->area : mpq_class(sd->area / base));
    if (sd->area == 0 && same_area) as.verdict = Verdict::exact_area;
    else if (*as.symdiff_area <= *pa.bound) as.verdict = Verdict::rounding_only;
    else as.verdict = Verdict::wrong;
    if (sd->area == 0 && !same_area) add_note("empty symmetric difference but a different area");
  }
  if (invalid) as.verdict = Verdict::invalid_output;
  return pa;
}

PointCheck independent_point_check(const Polygon& a, const Polygon& b, Operation op, const ExactResult& ref,
                                   const std::vector<ExactCycle>& other, bool other_unbounded) {
  PointCheck out;
  // The symmetric difference of the two results (nesting-parity regions of their rings).
  BasicPolygon<RationalPoint> x, y;
  x.rings = rings_of(ref.cycles);
  y.rings = rings_of(other);
  BooleanResult<RationalKernel> diff;
  try {
    diff = boolean_op<RationalKernel>(x, y, Options{Operation::symmetric_difference, true});
  } catch (const std::exception&) {
    return out;
  }
  Rings all;
  for (const auto& c : diff.cycles) {
    if (c.vertices.size() < 3) continue;
    all.emplace_back();
    for (const int v : c.vertices) all.back().push_back(diff.vertex(v));
  }
  if (all.empty()) return out;
  // Horizontal lines between consecutive distinct vertex heights cross the region's
  // boundary at no vertex; the midpoint of a crossing interval inside it is the point.
  std::vector<mpq_class> ys;
  for (const auto& r : all) {
    for (const auto& p : r) ys.push_back(p.y);
  }
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  const Rings ra = rings_of(a), rb = rings_of(b), rr = rings_of(ref.cycles), ro = rings_of(other);
  for (std::size_t k = 0; k + 1 < ys.size() && k < 64; ++k) {
    const mpq_class y0 = (ys[k] + ys[k + 1]) / 2;
    std::vector<mpq_class> xs;
    for (const auto& r : all) {
      for (std::size_t i = 0; i < r.size(); ++i) {
        const auto& p = r[i];
        const auto& q = r[(i + 1) % r.size()];
        if ((p.y > y0) != (q.y > y0)) xs.push_back(p.x + (q.x - p.x) * (y0 - p.y) / (q.y - p.y));
      }
    }
    std::sort(xs.begin(), xs.end());
    for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
      if (xs[i] == xs[i + 1]) continue;
      const RationalPoint p{mpq_class((xs[i] + xs[i + 1]) / 2), y0};
      const auto in_a = is_in(ra, a.type == PolygonType::hole, p);
      const auto in_b = is_in(rb, b.type == PolygonType::hole, p);
      const auto in_r = is_in(rr, ref.unbounded, p);
      const auto in_o = is_in(ro, other_unbounded, p);
      if (!in_a || !in_b || !in_r || !in_o) continue;
      const bool expect = in_result(op, *in_a, *in_b);
      out.explanation = "point (" + std::to_string(RationalKernel::to_nearest(p.x)) + ", " +
                        std::to_string(RationalKernel::to_nearest(p.y)) + "): " + yes_no(*in_a) + " A, " + yes_no(*in_b) +
                        " B, so " + yes_no(expect) + " A " + std::string(operation_name(op)) + " B; mkbool " + yes_no(*in_r) +
                        ", other " + yes_no(*in_o);
      if (*in_r != expect) out.wrong = "mkbool";
      else if (*in_o != expect) out.wrong = "other";
      return out;
    }
  }
  return out;
}

Output peer_as_output(const PeerOutput& output) {
  Output out;
  out.polygons = output.polygons;
  out.unbounded = output.unbounded;
  for (const OgcPolygon& p : output.polygons) {
    for (std::size_t i = 0; i <= p.holes.size(); ++i) {
      OutputIrreducible o;
      o.vertices = i == 0 ? p.shell : p.holes[i - 1];
      o.type = i == 0 ? PolygonType::island : PolygonType::hole;
      double twice = 0;
      for (std::size_t k = 0; k < o.vertices.size(); ++k) {
        const Point& u = o.vertices[k];
        const Point& w = o.vertices[(k + 1) % o.vertices.size()];
        twice += u.x * w.y - w.x * u.y;
      }
      if ((twice > 0) != (i == 0)) std::reverse(o.vertices.begin(), o.vertices.end());
      out.irreducible.push_back(std::move(o));
    }
  }
  return out;
}

PeerOutput run_peer_on_case(const std::string& peer, const Case& c, Operation op) {
  const std::optional<MultiPolygon> a_ogc = c.a_ogc ? c.a_ogc : ogc_form(c.a);
  const std::optional<MultiPolygon> b_ogc = c.b_ogc ? c.b_ogc : ogc_form(c.b);
  return run_peer(peer, PeerInput{&c.a, a_ogc ? &*a_ogc : nullptr}, PeerInput{&c.b, b_ogc ? &*b_ogc : nullptr}, op);
}

bool is_failure(Verdict v) {
  switch (v) {
    case Verdict::exact_match:
    case Verdict::exact_area:
    case Verdict::rounding_only:
    case Verdict::refused:
    case Verdict::unjudged:
    case Verdict::unsupported:
    case Verdict::invalid_input: return false;
    default: return true;
  }
}

}  // namespace mk::experiments
