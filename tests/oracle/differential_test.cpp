// The randomized differential test of the exact kernels against independent references:
// `exact` and `rational` must give identical results, every regular result must be the
// region CGAL's exact Boolean operations (Epeck) give (regularized symmetric difference
// empty, exact areas equal as rationals), and every non-regular result must agree with the
// point-membership oracle at every sample point. Inputs come from families.hpp.
// [BRIEF §1] [BRIEF §3] (exact kernels agree on every input) [MK89 §3.1]
// Preconditions: CGAL 5.5 (Debian 12). Environment: MK_ORACLE_SEED (a number, or "random"),
// MK_ORACLE_OPERATIONS (how many operations to check; default 12000 in Release, fewer under
// the sanitizers: see kDefaultOperations).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/shoelace.hpp"
#include "core/boolean_op.hpp"
#include "core/canonical.hpp"
#include "tests/oracle/cgal_reference.hpp"
#include "tests/oracle/families.hpp"
#include "tests/oracle/membership.hpp"

namespace mk::oracle {
namespace {

// Operations per run: one operation is one (pair, operation, regular) computed by both
// exact kernels and checked. The sanitizer build (ASan + UBSan, -O1) is about 20x slower.
#ifdef MK_SANITIZE_BUILD
constexpr long kDefaultOperations = 800;
#else
constexpr long kDefaultOperations = 12000;
#endif
constexpr std::uint64_t kDefaultSeed = 20261124;

constexpr Operation kOps[] = {Operation::intersection, Operation::union_, Operation::difference,
                              Operation::symmetric_difference};

std::uint64_t seed_from_environment() {
  const char* s = std::getenv("MK_ORACLE_SEED");
  if (s == nullptr || *s == '\0') return kDefaultSeed;
  if (std::string(s) == "random") return std::random_device{}() * 0x9e3779b97f4a7c15ull + std::random_device{}();
  return std::strtoull(s, nullptr, 10);
}

long operations_from_environment() {
  const char* s = std::getenv("MK_ORACLE_OPERATIONS");
  return s != nullptr && *s != '\0' ? std::strtol(s, nullptr, 10) : kDefaultOperations;
}

template <class K>
Region result_region(const BooleanResult<K>& r) {
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
  const Region reg = result_region(r);
  for (std::size_t i = 0; i < r.cycles.size(); ++i) {
    auto& [type, vs] = out.emplace_back();
    type = r.cycles[i].type;
    for (const QPoint& p : reg.rings[i]) vs.push_back({p.x, p.y});
  }
  return canonical(std::move(out));
}

// The typed area of mkbool's result (islands add, holes subtract), which for an unbounded
// result is minus the area of its complement.
Q typed_result_area(const BooleanResult<RationalKernel>& r) {
  const Region reg = result_region(r);
  std::vector<std::size_t> index(r.cycles.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = i;
  return typed_area<Q>(
      index, [&](std::size_t i) -> const QRing& { return reg.rings[i]; },
      [&](std::size_t i) { return r.cycles[i].type == PolygonType::island; });
}

struct Tally {
  long operations = 0;
  long regular_vs_cgal = 0;
  SampleCounts nonregular_points;
  long cgal_faults = 0;  // CGAL's result contradicted by the oracle, mkbool's confirmed
  std::map<std::string, long> per_family;
};

// CGAL 5.5's Epeck decides the type of a line-line intersection on its interval
// approximation, which overflows for coordinates beyond about 2^340: two crossing edges
// then have no intersection, and Arr_segment_traits_2 fails an assertion (a segmentation
// fault in Release builds; CgalFaults.LineIntersectionBeyondTheIntervalRange shows it). So
// CGAL is handed every configuration scaled by an exact power of two that brings its
// largest coordinate into [1, 2): a similarity, which the set operations commute with, so
// mkbool's result (computed on the original coordinates) is scaled the same way before the
// comparison and its area by the square.
struct Frame {
  Q scale = 1;  // 2^-e, e the exponent of the largest coordinate of A and B

  static Frame of(const Region& a, const Region& b) {
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
  QPoint to_cgal(const QPoint& p) const { return {p.x * scale, p.y * scale}; }
  QPoint from_cgal(const QPoint& p) const { return {p.x / scale, p.y / scale}; }
  Region to_cgal(const Region& r) const {
    Region out{{}, r.complement};
    for (const auto& ring : r.rings) {
      QRing q;
      for (const QPoint& p : ring) q.push_back(to_cgal(p));
      out.rings.push_back(std::move(q));
    }
    return out;
  }
};

// Compares mkbool's regular result with CGAL's; on a difference, the membership oracle
// decides at a point where the two differ which one contradicts the operation. Returns a
// failure message, or empty.
std::string check_regular(Operation op, const Region& a, const Region& b, const Frame& frame, const CgalSet& ca,
                          const CgalSet& cb, const BooleanResult<RationalKernel>& r, Tally& tally,
                          const std::string& what) {
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

TEST(Differential, ExactKernelsAgreeWithCgalEpeckAndTheMembershipOracle) {
  const std::uint64_t seed = seed_from_environment();
  const long operations = operations_from_environment();
  std::cout << "MK_ORACLE_SEED=" << seed << " MK_ORACLE_OPERATIONS=" << operations << "\n";
  const auto t0 = std::chrono::steady_clock::now();
  Tally tally;
  for (std::size_t index = 0; tally.operations < operations; ++index) {
    std::mt19937_64 rng(seed + 0x9e3779b97f4a7c15ull * index);
    const GeneratedPair pair = random_pair(index, rng);
    const std::string what = "pair " + std::to_string(index) + " (" + pair.family + ", " + pair.transform +
                             ")\n  A " + describe(pair.a) + "\n  B " + describe(pair.b);
    if (std::getenv("MK_ORACLE_VERBOSE") != nullptr) std::cout << what << std::endl;
    const Region a = region_of(pair.a);
    const Region b = region_of(pair.b);
    const Frame frame = Frame::of(a, b);
    const CgalSet ca = CgalSet::of(frame.to_cgal(a));
    const CgalSet cb = CgalSet::of(frame.to_cgal(b));
    for (const Operation op : kOps) {
      for (const bool regular : {true, false}) {
        // Both EF organisations and pair searches take turns.
        const Options opt{op, regular, index % 2 ? EfOrganisation::sorted : EfOrganisation::hash,
                          index % 3 ? PairSearch::sweep : PairSearch::all_pairs};
        const std::string run = what + "\n  " + std::string(operation_name(op)) + (regular ? " regular" : " non-regular");
        const auto r = boolean_op<RationalKernel>(pair.a, pair.b, opt);
        const auto e = boolean_op<ExactKernel>(pair.a, pair.b, opt);
        ASSERT_EQ(e.unbounded, r.unbounded) << run;
        ASSERT_TRUE(canonical_of(e) == canonical_of(r)) << "exact and rational differ: " << run;
        if (regular) {
          const std::string failure = check_regular(op, a, b, frame, ca, cb, r, tally, run);
          ASSERT_TRUE(failure.empty()) << "against CGAL Epeck: " << failure << "\n" << run;
          ++tally.regular_vs_cgal;
        } else {
          const std::vector<QPoint> samples = sample_points(a, b, result_region(r), rng, 8);
          const std::string failure = first_contradiction(op, false, a, b, result_region(r), samples,
                                                          &tally.nonregular_points);
          ASSERT_TRUE(failure.empty()) << "membership oracle: " << failure << "\n" << run;
        }
        ++tally.operations;
        ++tally.per_family[pair.family];
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << tally.operations << " operations in " << seconds << " s: " << tally.regular_vs_cgal
            << " regular results equal to CGAL Epeck's (region and exact area), "
            << tally.operations - tally.regular_vs_cgal << " non-regular results checked at "
            << tally.nonregular_points.points << " sample points (" << tally.nonregular_points.on_both_boundaries
            << " on both inputs' boundaries); CGAL faults shown by the oracle: " << tally.cgal_faults
            << "\n";
  for (const auto& [family, n] : tally.per_family) std::cout << "  " << family << ": " << n << "\n";
  EXPECT_GE(tally.operations, operations);
}

}  // namespace
}  // namespace mk::oracle
