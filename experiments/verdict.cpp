// Verdicts against the exact reference: canonical comparison of irreducible result
// polygons, exact validity of rounded output, exact symmetric-difference area.
// [MK89 §3.3] [MK89 §3.1 step 6]
// Preconditions: see verdict.hpp.
#include "experiments/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "arithmetic/shoelace.hpp"
#include "api/mkbool.hpp"
#include "core/boolean_op.hpp"
#include "core/canonical.hpp"
#include "core/to_output.hpp"

namespace mk::experiments {

std::string_view verdict_name(Verdict v) {
  switch (v) {
    case Verdict::exact_match: return "exact_match";
    case Verdict::valid_different: return "valid_different";
    case Verdict::invalid_output: return "invalid_output";
    case Verdict::error: return "error";
    case Verdict::timeout: return "timeout";
    case Verdict::crash: return "crash";
    case Verdict::invalid_input: return "invalid_input";
    case Verdict::exact_area: return "exact_area";
    case Verdict::rounding_only: return "rounding_only";
    case Verdict::wrong: return "wrong";
    case Verdict::exception: return "exception";
    case Verdict::refused: return "refused";
    case Verdict::unjudged: return "unjudged";
    case Verdict::unsupported: return "unsupported";
  }
  return "?";
}

std::optional<Verdict> parse_verdict(std::string_view name) {
  for (const Verdict v : all_verdicts) {
    if (verdict_name(v) == name) return v;
  }
  for (const Verdict v : peer_verdicts) {
    if (verdict_name(v) == name) return v;
  }
  return std::nullopt;
}

mpq_class twice_signed_area(const std::vector<RationalPoint>& r) { return mk::twice_signed_area<mpq_class>(r); }

// Islands add, holes subtract: the area of a bounded result from its typed cycles.
mpq_class typed_area(const std::vector<ExactCycle>& cycles) {
  return mk::typed_area<mpq_class>(
      cycles, [](const ExactCycle& c) -> const std::vector<RationalPoint>& { return c.vertices; },
      [](const ExactCycle& c) { return c.type == PolygonType::island; });
}

namespace {

template <class V, class Less>
bool same_cycles(std::vector<CanonicalCycle<V>> x, std::vector<CanonicalCycle<V>> y, Less less, std::string& note) {
  if (x.size() != y.size()) {
    note = std::to_string(x.size()) + " result polygons instead of " + std::to_string(y.size());
    return false;
  }
  x = canonical(std::move(x), less);
  y = canonical(std::move(y), less);
  const auto equal = [&](const V& p, const V& q) { return !less(p, q) && !less(q, p); };
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].first != y[i].first ||
        !std::equal(x[i].second.begin(), x[i].second.end(), y[i].second.begin(), y[i].second.end(), equal)) {
      note = "result polygon " + std::to_string(i) + " (sorted) differs";
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<ExactCycle> exact_cycles(const Output& output) {
  std::vector<ExactCycle> out;
  for (const auto& c : output.irreducible) {
    ExactCycle e{c.type, {}};
    for (std::size_t i = 0; i < c.vertices.size(); ++i) {
      if (c.exact.size() == 2 * c.vertices.size()) {
        mpq_class x(c.exact[2 * i]), y(c.exact[2 * i + 1]);
        x.canonicalize();
        y.canonicalize();
        e.vertices.push_back({x, y});
      } else {
        e.vertices.push_back(RationalKernel::point(c.vertices[i]));
      }
    }
    out.push_back(std::move(e));
  }
  return out;
}

ExactResult exact_result_of(Output output) {
  ExactResult out;
  out.output = std::move(output);
  out.unbounded = out.output.unbounded;
  out.cycles = exact_cycles(out.output);
  if (!out.unbounded) out.area = typed_area(out.cycles);
  return out;
}

ExactResult exact_reference(const Polygon& a, const Polygon& b, Operation op, bool regular, bool paper_variants,
                            std::optional<FillRule> fill_rule) {
  if (fill_rule) {
    BooleanOptions o{op, regular, "rational"};
    o.fill_rule = fill_rule;
    o.all_pairs = paper_variants;
    o.area = false;
    o.exact_coordinates = true;
    return exact_result_of(compute(a, b, o).output);
  }
  const Options opt{op, regular, paper_variants ? EfOrganisation::sorted : EfOrganisation::hash,
                    paper_variants ? PairSearch::all_pairs : PairSearch::sweep};
  const BooleanResult<RationalKernel> r = boolean_op<RationalKernel>(a, b, opt);
  ExactResult out;
  out.unbounded = r.unbounded;
  for (const auto& c : r.cycles) {
    ExactCycle e{c.type, {}};
    for (const int v : c.vertices) e.vertices.push_back(r.vertex(v));
    out.cycles.push_back(std::move(e));
  }
  if (!out.unbounded) out.area = typed_area(out.cycles);
  out.output = to_output<RationalKernel, RationalKernel>(r);
  return out;
}

// Whether the result's regions overlap at a vertex where rings meet. Every result cycle
// has the region on one side (left when counterclockwise cycles are islands), so turning
// counterclockwise around a vertex, each pass of a cycle has one edge where the turn enters
// the region and one where it leaves it; in a valid output enters and leaves alternate.
// Edges that do not cross can still overlap regions through two shared vertices.
bool have_overlapping_sectors(const Output& output, bool region_left) {
  struct Pass {
    Point from, to;  // the edge where a counterclockwise turn enters the region, and leaves it
  };
  std::map<std::pair<double, double>, std::vector<Pass>> at;
  for (const auto& c : output.irreducible) {
    const auto& r = c.vertices;
    if (r.size() < 3) continue;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point& u = r[(i + r.size() - 1) % r.size()];
      const Point& v = r[i];
      const Point& w = r[(i + 1) % r.size()];
      at[{v.x, v.y}].push_back(region_left ? Pass{w, u} : Pass{u, w});
    }
  }
  for (const auto& [key, passes] : at) {
    if (passes.size() < 2) continue;
    const RationalPoint v{mpq_class(key.first), mpq_class(key.second)};
    struct Ray {
      mpq_class dx, dy;
      std::size_t pass;
      bool start;
    };
    std::vector<Ray> rays;
    for (std::size_t p = 0; p < passes.size(); ++p) {
      rays.push_back({mpq_class(passes[p].from.x) - v.x, mpq_class(passes[p].from.y) - v.y, p, true});
      rays.push_back({mpq_class(passes[p].to.x) - v.x, mpq_class(passes[p].to.y) - v.y, p, false});
    }
    const auto half = [](const Ray& r) { return r.dy > 0 || (r.dy == 0 && r.dx > 0) ? 0 : 1; };
    const auto cross = [](const Ray& a, const Ray& b) { return sgn(a.dx * b.dy - a.dy * b.dx); };
    std::sort(rays.begin(), rays.end(), [&](const Ray& a, const Ray& b) {
      return half(a) != half(b) ? half(a) < half(b) : cross(a, b) > 0;
    });
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Ray& a = rays[i];
      const Ray& b = rays[(i + 1) % rays.size()];
      if (half(a) == half(b) && cross(a, b) == 0) return true;  // two edges along one ray
      if (a.start == b.start) return true;  // entering twice (or leaving twice): regions overlap
    }
  }
  return false;
}

bool is_valid_output(const Output& output, PolygonType ccw_type, std::string* why) {
  std::vector<std::vector<Point>> rings;
  for (const auto& c : output.irreducible) rings.push_back(c.vertices);
  // For exact results (exact coordinates given) the library's exact OGC check of the
  // rounded polygons (GEOS's rules: repeated consecutive points allowed) decides; rounded
  // kernels' outputs, whose polygons the library assembled from inexact decisions, get the
  // ring and sector checks.
  const bool exact = std::any_of(output.irreducible.begin(), output.irreducible.end(),
                                 [](const OutputIrreducible& c) { return !c.exact.empty(); });
  const bool library_says_valid = exact && output.rounded_valid == true;
  if (!library_says_valid && !is_valid_rounded_output<RationalKernel>(rings)) {
    if (why) *why = "rounded edges cross, overlap or touch, or a ring collapses";
    return false;
  }
  if (!library_says_valid && have_overlapping_sectors(output, ccw_type == PolygonType::island)) {
    if (why) *why = "result polygons overlap at a shared vertex";
    return false;
  }
  for (std::size_t i = 0; i < output.irreducible.size(); ++i) {
    const auto& c = output.irreducible[i];
    if (c.vertices.size() < 3) continue;
    std::vector<RationalPoint> r;
    for (const auto& v : c.vertices) r.push_back(RationalKernel::point(v));
    const int s = sgn(twice_signed_area<mpq_class>(r));
    if (s == 0 || (s > 0) != (c.type == ccw_type)) {
      if (why) *why = "result polygon " + std::to_string(i) + ": orientation contradicts its type";
      return false;
    }
  }
  return true;
}

namespace {

bool is_on_segment(const RationalPoint& a, const RationalPoint& b, const RationalPoint& p) {
  if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) != 0) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Whether p lies inside ring r (crossing parity; p not on r).
bool is_inside(const std::vector<RationalPoint>& r, const RationalPoint& p) {
  bool in = false;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const auto& a = r[i];
    const auto& b = r[(i + 1) % r.size()];
    if ((a.y > p.y) != (b.y > p.y)) {
      const mpq_class cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
      if (b.y > a.y ? cross > 0 : cross < 0) in = !in;
    }
  }
  return in;
}

}  // namespace

// Rings of a valid output do not cross, so the interior of each edge lies on one side of
// every other ring: its midpoint decides the nesting (quadratic, hence the limit).
std::optional<mpq_class> parity_area(const std::vector<std::vector<RationalPoint>>& rings) {
  if (rings.size() > 64) return std::nullopt;
  mpq_class total = 0;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    int depth = 0;
    for (std::size_t j = 0; j < rings.size(); ++j) {
      if (i == j) continue;
      bool decided = false;
      for (std::size_t k = 0; k < rings[i].size() && !decided; ++k) {
        const auto& a = rings[i][k];
        const auto& b = rings[i][(k + 1) % rings[i].size()];
        const RationalPoint m{(a.x + b.x) / 2, (a.y + b.y) / 2};
        bool on = false;
        for (std::size_t e = 0; e < rings[j].size() && !on; ++e) {
          on = is_on_segment(rings[j][e], rings[j][(e + 1) % rings[j].size()], m);
        }
        if (on) continue;
        decided = true;
        if (is_inside(rings[j], m)) ++depth;
      }
      if (!decided) return std::nullopt;
    }
    const mpq_class a = abs(twice_signed_area<mpq_class>(rings[i])) / 2;
    total += depth % 2 == 0 ? a : mpq_class(-a);
  }
  return total;
}

namespace {

mpq_class result_area(const BooleanResult<RationalKernel>& r) {
  std::vector<ExactCycle> cycles;
  for (const auto& c : r.cycles) {
    ExactCycle ec{c.type, {}};
    for (const int v : c.vertices) ec.vertices.push_back(r.vertex(v));
    cycles.push_back(std::move(ec));
  }
  return typed_area(cycles);
}

}  // namespace

std::optional<std::string> violated_identity(const Polygon& x, const Polygon& y) {
  const auto rings = [](const Polygon& p) {
    std::vector<std::vector<RationalPoint>> out;
    for (const auto& r : p.rings) {
      out.emplace_back();
      for (const auto& v : r) out.back().push_back(RationalKernel::point(v));
    }
    return out;
  };
  // The identities hold for valid outputs (no ring touches itself or another ring except
  // at shared vertices); for anything else parity areas are not the region's area.
  if (!is_valid_rounded_output<RationalKernel>(x.rings) || !is_valid_rounded_output<RationalKernel>(y.rings)) {
    return std::nullopt;
  }
  try {
    const auto ax = parity_area(rings(x)), ay = parity_area(rings(y));
    if (!ax || !ay) return std::nullopt;
    const auto xx = boolean_op<RationalKernel>(x, x, Options{Operation::intersection, true});
    if (result_area(xx) != *ax) {
      return "area(A and A) = " + result_area(xx).get_str() + " but A's area is " + ax->get_str();
    }
    const auto both = boolean_op<RationalKernel>(x, y, Options{Operation::intersection, true});
    const auto either = boolean_op<RationalKernel>(x, y, Options{Operation::symmetric_difference, true});
    const mpq_class expect = *ax + *ay - 2 * result_area(both);
    if (result_area(either) != expect) {
      return "area(A xor B) = " + result_area(either).get_str() + " but area(A) + area(B) - 2 area(A and B) = " +
             expect.get_str();
    }
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::optional<SymmetricDifference> symmetric_difference_area(const std::vector<ExactCycle>& x, bool x_unbounded,
                                                             const std::vector<ExactCycle>& y, bool y_unbounded) {
  if (x_unbounded != y_unbounded) return SymmetricDifference{true, 0, std::nullopt};
  // Two unbounded regions differ where their complements do: compare the finite area
  // regions as islands.
  const auto as_polygon = [](const std::vector<ExactCycle>& cycles) {
    BasicPolygon<RationalPoint> p;
    for (const auto& c : cycles) {
      if (c.vertices.size() < 3) continue;  // dangling edges and points have no area
      std::vector<RationalPoint> ring;
      for (const auto& v : c.vertices) {
        if (ring.empty() || !(ring.back() == v)) ring.push_back(v);
      }
      while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
      p.rings.push_back(std::move(ring));
    }
    return p;
  };
  try {
    const auto p = as_polygon(x), q = as_polygon(y);
    const auto xor_result = boolean_op<RationalKernel>(p, q, Options{Operation::symmetric_difference, true});
    if (xor_result.unbounded) return SymmetricDifference{true, 0, std::nullopt};
    SymmetricDifference out{false, result_area(xor_result), std::nullopt};
    // Check the core against itself and against the parity areas:
    // area(P xor Q) = area(P) + area(Q) - 2 area(P and Q).
    const auto ap = parity_area(p.rings), aq = parity_area(q.rings);
    if (ap && aq) {
      const auto both = boolean_op<RationalKernel>(p, q, Options{Operation::intersection, true});
      out.consistent = !both.unbounded && out.area == *ap + *aq - 2 * result_area(both);
    }
    return out;
  } catch (const std::exception&) {
    return std::nullopt;  // the output's rings cross: no region to compare
  }
}

PolygonType ccw_type_of(const ExactResult& ref) {
  for (const auto& c : ref.cycles) {
    if (c.vertices.size() < 3) continue;
    return sgn(twice_signed_area<mpq_class>(c.vertices)) > 0 ? c.type : opposite(c.type);
  }
  return PolygonType::island;
}

Assessment assess(const Output& output, const ExactResult& ref) {
  Assessment out;
  // A rounded construction can overflow or divide by zero: such an output is invalid, and
  // nothing exact can be computed from it (GMP traps on non-finite values).
  for (std::size_t i = 0; i < output.irreducible.size(); ++i) {
    for (const Point& v : output.irreducible[i].vertices) {
      if (!std::isfinite(v.x) || !std::isfinite(v.y)) {
        out.verdict = Verdict::invalid_output;
        out.note = "result polygon " + std::to_string(i) + " has a non-finite coordinate";
        return out;
      }
    }
  }
  const bool exact = std::any_of(output.irreducible.begin(), output.irreducible.end(),
                                 [](const OutputIrreducible& c) { return !c.exact.empty(); }) ||
                     (output.irreducible.empty() && output.rounded_valid.has_value());
  bool match = output.unbounded == ref.unbounded;
  if (!match) out.note = output.unbounded ? "unbounded, exact result bounded" : "bounded, exact result unbounded";
  if (match && exact) {
    const auto less = [](const RationalPoint& p, const RationalPoint& q) { return p.x != q.x ? p.x < q.x : p.y < q.y; };
    std::vector<CanonicalCycle<RationalPoint>> x, y;
    for (const auto& c : exact_cycles(output)) x.push_back({c.type, c.vertices});
    for (const auto& c : ref.cycles) y.push_back({c.type, c.vertices});
    match = same_cycles(std::move(x), std::move(y), less, out.note);
  } else if (match) {
    const auto less = [](const Point& p, const Point& q) { return p.x != q.x ? p.x < q.x : p.y < q.y; };
    std::vector<CanonicalCycle<Point>> x, y;
    for (const auto& c : output.irreducible) x.push_back({c.type, c.vertices});
    for (const auto& c : ref.output.irreducible) y.push_back({c.type, c.vertices});
    match = same_cycles(std::move(x), std::move(y), less, out.note);
  }
  if (match) {
    out.verdict = Verdict::exact_match;
    out.symdiff_area = 0;
    out.area_error = 0;
    return out;
  }
  std::string why;
  out.verdict = is_valid_output(output, ccw_type_of(ref), &why) ? Verdict::valid_different : Verdict::invalid_output;
  if (out.verdict == Verdict::invalid_output) out.note = why + "; " + out.note;
  // The exact overlay of two results of thousands of polygons takes minutes; past the
  // limit the area error is left unmeasured (empty), which the note says.
  if (ref.cycles.size() + output.irreducible.size() > symdiff_polygon_limit) {
    out.note += "; area error not measured (" + std::to_string(ref.cycles.size() + output.irreducible.size()) +
                " result polygons)";
    return out;
  }
  const auto sd = symmetric_difference_area(exact_cycles(output), output.unbounded, ref.cycles, ref.unbounded);
  if (sd && sd->consistent == false && out.verdict == Verdict::valid_different) {
    // RationalKernel disagrees with exact parity areas on these rings: a bug of the core
    // or an exact kernel, reported rather than trusted.
    out.note += "; [reference inconsistency] area(K xor R) != area(K) + area(R) - 2 area(K and R)";
  }
  if (sd) {
    if (sd->infinite) {
      out.symdiff_area = out.area_error = std::numeric_limits<double>::infinity();
    } else {
      out.symdiff_area = RationalKernel::to_nearest(sd->area);
      const mpq_class base = ref.unbounded ? mpq_class(0) : mpq_class(abs(ref.area));
      out.area_error = RationalKernel::to_nearest(base == 0 ? sd->area : mpq_class(sd->area / base));
    }
  }
  return out;
}

}  // namespace mk::experiments
