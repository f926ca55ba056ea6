// One operation checked against every independent reference (see checks.hpp).
// [BRIEF §1] [BRIEF §3]
// Preconditions: see checks.hpp.
#include "tests/oracle/checks.hpp"

#include <algorithm>
#include <iostream>
#include <vector>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/shoelace.hpp"
#include "core/canonical.hpp"

namespace mk::oracle {

Frame Frame::of(const Region& a, const Region& b) {
  Q largest = 0;
  for (const Region* r : {&a, &b}) {
    for (const auto& ring : r->rings) {
      for (const QPoint& p : ring) largest = std::max({largest, Q(abs(p.x)), Q(abs(p.y))});
    }
  }
  Frame f;
  if (largest == 0) return f;
  while (f.scale * largest >= 2) f.scale /= 2;
  while (f.scale * largest < 1) f.scale *= 2;
  return f;
}

Region Frame::to_cgal(const Region& r) const {
  Region out{{}, r.complement};
  for (const auto& ring : r.rings) {
    QRing q;
    for (const QPoint& p : ring) q.push_back(to_cgal(p));
    out.rings.push_back(std::move(q));
  }
  return out;
}

References References::of(const Polygon& a, const Polygon& b) {
  References r{region_of(a), region_of(b), {}, {}, {}};
  r.frame = Frame::of(r.a, r.b);
  r.cgal_a = CgalSet::of(r.frame.to_cgal(r.a));
  r.cgal_b = CgalSet::of(r.frame.to_cgal(r.b));
  return r;
}

namespace {

template <class K>
Region region_of_result(const BooleanResult<K>& r) {
  Region out;
  out.complement = r.unbounded;
  for (const auto& c : r.cycles) {
    QRing ring;
    for (const int v : c.vertices) {
      if constexpr (std::is_same_v<K, RationalKernel>) {
        ring.push_back(r.vertex(v));
      } else {
        ring.push_back(K::exact(r.vertex(v)));
      }
    }
    out.rings.push_back(std::move(ring));
  }
  return out;
}

template <class K>
std::vector<CanonicalCycle<std::pair<Q, Q>>> canonical_of(const BooleanResult<K>& r) {
  std::vector<CanonicalCycle<std::pair<Q, Q>>> out;
  const Region reg = region_of_result(r);
  for (std::size_t i = 0; i < r.cycles.size(); ++i) {
    auto& [type, vs] = out.emplace_back();
    type = r.cycles[i].type;
    for (const QPoint& p : reg.rings[i]) vs.push_back({p.x, p.y});
  }
  return canonical(std::move(out));
}

// Compares mkbool's regular result with CGAL's; on a difference, the membership oracle
// decides at a point where the two differ which one contradicts the operation. Returns a
// failure message, or empty.
std::string check_regular(Operation op, const References& refs, const BooleanResult<RationalKernel>& r, Tally& tally,
                          const std::string& what) {
  const Region& a = refs.a;
  const Region& b = refs.b;
  const Frame& frame = refs.frame;
  const CgalSet& ca = refs.cgal_a;
  const CgalSet& cb = refs.cgal_b;
  const Region rr = result_region(r);
  CgalSet ours;
  try {
    ours = CgalSet::of(frame.to_cgal(rr));
  } catch (const CgalRegionError& e) {
    return "mkbool's result has " + std::string(e.what());
  }
  const CgalSet theirs = ca.apply(op, cb);
  // An unbounded result: the typed area is minus the area of the complement.
  const std::optional<Q> their_area = r.unbounded ? theirs.complement().area() : theirs.area();
  const Q our_area = (r.unbounded ? Q(-typed_result_area(r)) : typed_result_area(r)) * frame.scale * frame.scale;
  const bool same = ours.same_as(theirs);
  if (same && their_area && *their_area == our_area) return {};
  // They differ: find a point where, and ask the oracle.
  std::string why = same ? "same region, but area " + our_area.get_str() + " (typed, mkbool) vs " +
                               (their_area ? their_area->get_str() : std::string("unbounded")) + " (CGAL), scaled by " +
                               frame.scale.get_str()
                         : "regions differ";
  if (same) return why;
  if (const auto q = ours.apply(Operation::symmetric_difference, theirs).interior_point()) {
    const QPoint p = frame.from_cgal(*q);
    const Location want = expected_location(op, true, a, b, p);
    const Location mk = locate(rr, p);
    const Location cgal = theirs.locate(*q);
    why += " at " + show(p) + ": the operation says " + location_name(want) + ", mkbool " + location_name(mk) +
           ", CGAL " + location_name(cgal);
    if (mk == want && cgal != want) {
      ++tally.cgal_faults;
      std::cout << "CGAL fault (shown by the membership oracle): " << what << ": " << why << "\n";
      return {};
    }
  }
  return why;
}

}  // namespace

Region result_region(const BooleanResult<RationalKernel>& r) { return region_of_result(r); }

// The typed area of mkbool's result (islands add, holes subtract), which for an unbounded
// result is minus the area of its complement.
Q typed_result_area(const BooleanResult<RationalKernel>& r) {
  const Region reg = region_of_result(r);
  std::vector<std::size_t> index(r.cycles.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = i;
  return typed_area<Q>(
      index, [&](std::size_t i) -> const QRing& { return reg.rings[i]; },
      [&](std::size_t i) { return r.cycles[i].type == PolygonType::island; });
}

std::string check_operation(const Polygon& a, const Polygon& b, const References& refs, const Options& opt,
                            std::mt19937_64& rng, Tally& tally, const std::string& what) {
  ++tally.operations;
  BooleanResult<RationalKernel> r;
  BooleanResult<ExactKernel> e;
  try {
    r = boolean_op<RationalKernel>(a, b, opt);
    e = boolean_op<ExactKernel>(a, b, opt);
  } catch (const std::exception& ex) {
    return std::string("mkbool failed: ") + ex.what();  // exact kernels never fail on inputs in the domain
  }
  if (e.unbounded != r.unbounded || canonical_of(e) != canonical_of(r)) return "exact and rational differ";
  const Region result = result_region(r);
  if (opt.regular) {
    ++tally.regular_vs_cgal;
    const std::string failure = check_regular(opt.op, refs, r, tally, what);
    return failure.empty() ? failure : "against CGAL Epeck: " + failure;
  }
  const std::string failure = first_contradiction(opt.op, false, refs.a, refs.b, result,
                                                  sample_points(refs.a, refs.b, result, rng, 8), &tally.nonregular_points);
  return failure.empty() ? failure : "membership oracle: " + failure;
}

}  // namespace mk::oracle
