// Tests of the peer back ends and their verdicts: Wilson intervals, OGC forms and the
// exact OGC check, each peer on a case it must get exactly right, the known CGAL fault with
// the independent point check, the oracle_agrees column, the outcome scale, and the corpus
// reader. [BRIEF §5] [OGC06-103 §6.1.11]
// Preconditions: peers present as built (each test covers the peers this build has).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include "arithmetic/nearest_double.hpp"
#include "experiments/external_cases.hpp"
#include "experiments/ogc.hpp"
#include "experiments/peer_verdict.hpp"
#include "experiments/report_library.hpp"
#include "experiments/runner.hpp"
#include "experiments/statistics.hpp"
#include "io/wkt.hpp"

namespace mk::experiments {
namespace {

namespace fs = std::filesystem;

Polygon poly(const std::string& wkt) { return to_polygon(read_wkt(wkt)); }

TEST(Statistics, WilsonIntervalsMatchHandComputedValues) {
  // z = 1.96: 0 of 10 -> [0, z^2 / (10 + z^2)]; 5 of 10 -> 0.5 -/+ 0.2634.
  auto [lo, hi] = wilson_interval(0, 10);
  EXPECT_EQ(lo, 0.0);
  EXPECT_NEAR(hi, 0.27753, 1e-5);
  std::tie(lo, hi) = wilson_interval(10, 10);
  EXPECT_NEAR(lo, 0.72247, 1e-5);
  EXPECT_EQ(hi, 1.0);
  std::tie(lo, hi) = wilson_interval(5, 10);
  EXPECT_NEAR(lo, 0.23659, 1e-5);
  EXPECT_NEAR(hi, 0.76341, 1e-5);
  EXPECT_EQ(rate_with_interval(0, 10), "0 [0–28%]");
  EXPECT_EQ(rate_with_interval(5, 10), "50% (5) [24%–76%]");
  EXPECT_EQ(percent(13912.0 / 13920), "99.94%");  // never rounded up to 100%
}

TEST(Ogc, NestingGivesShellsWithTheirHoles) {
  Polygon p;  // a square, a hole in it, an island in the hole, listed out of order
  p.rings = {{{3, 3}, {5, 3}, {5, 5}, {3, 5}}, {{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {8, 2}, {8, 8}, {2, 8}}};
  const auto mp = ogc_form(p);
  ASSERT_TRUE(mp);
  ASSERT_EQ(mp->size(), 2u);
  EXPECT_EQ((*mp)[0].shell.size(), 4u);
  EXPECT_TRUE((*mp)[0].holes.empty());  // the island in the hole (depth 2) comes first, in ring order
  EXPECT_EQ((*mp)[1].holes.size(), 1u);
  p.type = PolygonType::hole;
  EXPECT_FALSE(ogc_form(p));
}

TEST(Ogc, ExactCheckFollowsOgcRules) {
  std::string why;
  // A hole touching its shell at one point: valid (touching is allowed at points), also
  // when the point is inside a shell edge rather than a shell vertex.
  EXPECT_TRUE(is_valid_ogc_exact(read_wkt("POLYGON((0 0,4 0,4 4,0 4,0 0),(0 2,2 1,2 3,0 2))"), &why)) << why;
  EXPECT_EQ(geos_is_valid(read_wkt("POLYGON((0 0,4 0,4 4,0 4,0 0),(0 2,2 1,2 3,0 2))")).value_or(true), true);
  // A hole outside its shell, overlapping parts, a crossing ring: invalid.
  EXPECT_FALSE(is_valid_ogc_exact(read_wkt("POLYGON((0 0,4 0,4 4,0 4,0 0),(5 5,6 5,6 6,5 6,5 5))"), &why));
  EXPECT_FALSE(is_valid_ogc_exact(read_wkt("MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)),((1 1,3 1,3 3,1 3,1 1)))"), &why));
  EXPECT_FALSE(is_valid_ogc_exact({{{{0, 0}, {2, 0}, {0, 2}, {2, 2}}, {}}}, &why));
  // Two parts meeting at a vertex where their regions overlap (one inside the other's corner).
  EXPECT_FALSE(is_valid_ogc_exact(read_wkt("MULTIPOLYGON(((0 0,4 0,4 4,0 4,0 0)),((0 0,1 2,2 1,0 0)))"), &why));
}

// GEOS is asked about the copy scaled exactly into its range: mkbool's output (certified
// rounding) for a 10-point star at 1e-151 intersected with its copy moved by one ulp in x,
// three slivers an ulp or two wide, which GEOS 3.11 called a self-intersection as written
// (its orientation products of ulp differences underflow) and valid once scaled by 2^499.
TEST(Ogc, GeosIsAskedAboutAnExactlyScaledCopy) {
  const MultiPolygon slivers = read_wkt(
      "MULTIPOLYGON (((2.357850691896153e-151 7.25671825756607e-151, 2.357850691896153e-151 7.25671825756607e-151, -9.270509831248419e-152 2.853169548885461e-151, -9.270509831248417e-152 2.853169548885461e-151, 2.357850691896153e-151 7.25671825756607e-151)), ((-6.602190018309403e-151 4.7967718262742754e-151, -6.602190018309404e-151 4.796771826274276e-151, -2.9999999999999998e-151 3.67394039744206e-167, -5.670509622053321e-151 -4.119866395885342e-151, -5.67050962205332e-151 -4.119866395885342e-151, -2.9999999999999995e-151 3.67394039744206e-167, -6.602190018309403e-151 4.7967718262742754e-151)), ((-9.270509831248426e-152 -2.8531695488854605e-151, 2.375136448950187e-151 -7.309918347478887e-151, 2.375136448950187e-151 -7.309918347478887e-151, -9.270509831248424e-152 -2.8531695488854605e-151, -9.270509831248426e-152 -2.8531695488854605e-151)))");
  std::string why;
  EXPECT_TRUE(is_valid_ogc_exact(slivers, &why)) << why;
  const std::optional<GeosValidityCopy> copy = geos_validity_copy(slivers);
  ASSERT_TRUE(copy);
  EXPECT_EQ(copy->shift, 499);  // the largest magnitude, 7.3e-151, is 1.82 * 2^-499
  ASSERT_EQ(copy->polygons.size(), slivers.size());
  for (std::size_t i = 0; i < slivers.size(); ++i) {
    ASSERT_EQ(copy->polygons[i].shell.size(), slivers[i].shell.size());
    for (std::size_t k = 0; k < slivers[i].shell.size(); ++k) {
      // Exact: scaling back gives the written coordinates bit for bit.
      EXPECT_EQ(std::ldexp(copy->polygons[i].shell[k].x, -499), slivers[i].shell[k].x);
      EXPECT_EQ(std::ldexp(copy->polygons[i].shell[k].y, -499), slivers[i].shell[k].y);
    }
  }
  // A bow tie at the same scale stays invalid for both.
  const MultiPolygon bow_tie = read_wkt("POLYGON((0 0,2e-150 0,0 2e-150,2e-150 2e-150,0 0))");
  EXPECT_FALSE(is_valid_ogc_exact(bow_tie, &why));
  // A spread beyond 2^400 (or a coordinate that is not finite): GEOS is not asked.
  EXPECT_FALSE(geos_validity_copy(read_wkt("POLYGON((0 0,1 0,1 1e-200,0 0))")));
  EXPECT_FALSE(geos_is_valid(read_wkt("POLYGON((0 0,1 0,1 1e-200,0 0))")));
  EXPECT_TRUE(geos_validity_copy(read_wkt("POLYGON((0 0,1 0,1 1e-120,0 0))")));
  EXPECT_FALSE(geos_validity_copy({{{{0, 0}, {HUGE_VAL, 0}, {0, 1}}, {}}}));
  if (!is_peer("geos")) GTEST_SKIP() << "built without GEOS: its verdicts are not asked";
  EXPECT_EQ(geos_is_valid(slivers, &why), true) << why;
  EXPECT_EQ(geos_is_valid(bow_tie, &why), false);
  EXPECT_NE(why.find("(coordinates multiplied by 2^"), std::string::npos) << why;
  // Near the largest doubles too (scaled by 2^-1023).
  EXPECT_EQ(geos_is_valid(read_wkt("POLYGON((0 0,1e308 0,1e308 1e308,0 1e308,0 0))")), true);
}

TEST(Peers, EveryPeerGetsTwoOverlappingSquaresExactly) {
  const Polygon a = poly("POLYGON((0 0,2 0,2 2,0 2,0 0))"), b = poly("POLYGON((1 1,3 1,3 3,1 3,1 1))");
  const MultiPolygon ao = read_wkt("POLYGON((0 0,2 0,2 2,0 2,0 0))"), bo = read_wkt("POLYGON((1 1,3 1,3 3,1 3,1 1))");
  for (const auto peer : peer_names()) {
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference, Operation::symmetric_difference}) {
      const ExactResult ref = exact_reference(a, b, op, true, true);
      const PeerOutput out = run_peer(peer, {&a, &ao}, {&b, &bo}, op);
      const PeerAssessment pa = assess_peer(out, &ref, input_resolution(a, b));
      EXPECT_EQ(pa.assessment.verdict, Verdict::exact_area) << peer << " " << operation_name(op) << ": " << pa.assessment.note;
      EXPECT_EQ(pa.assessment.symdiff_area.value_or(-1), 0.0);
    }
  }
}

TEST(Peers, HoleTypeInputIsUnsupportedByOgcLibraries) {
  Polygon a = poly("POLYGON((0 0,2 0,2 2,0 2,0 0))");
  a.type = PolygonType::hole;
  const Polygon b = poly("POLYGON((1 1,3 1,3 3,1 3,1 1))");
  for (const auto peer : peer_names()) {
    if (peer == "cgal_epeck") {
      // CGAL takes the complement: A is the outside of the square.
      const PeerOutput out = run_peer(peer, {&a, nullptr}, {&b, nullptr}, Operation::intersection);
      const ExactResult ref = exact_reference(a, b, Operation::intersection, true, true);
      EXPECT_EQ(assess_peer(out, &ref, input_resolution(a, b)).assessment.verdict, Verdict::exact_area);
    } else {
      EXPECT_THROW(run_peer(peer, {&a, nullptr}, {&b, nullptr}, Operation::intersection), PeerUnsupported) << peer;
    }
  }
}

TEST(Peers, KnownCgalFaultIsFoundAndBlamedOnCgalByThePointCheck) {
  if (!is_peer("cgal_epeck")) GTEST_SKIP() << "built without CGAL";
  // shared/design/public-failure-reports.md: CGAL 5.5 gives area 59, the exact answer is 45.
  const std::string wa = "POLYGON((2 0,2 4,-2 4,-6 2,-6 0,-4 -4,0 -4,2 -4,2 0))";
  const std::string wb = "POLYGON((4 0,0 4,0 2,-2 6,-6 0,0 -6,2 -4,6 -2,4 0),(2 2,0 0,2 0,2 2))";
  const Polygon a = poly(wa), b = poly(wb);
  const MultiPolygon ao = read_wkt(wa), bo = read_wkt(wb);
  const ExactResult ref = exact_reference(a, b, Operation::intersection, true, true);
  EXPECT_EQ(ref.area, 45);
  const PeerOutput out = run_peer("cgal_epeck", {&a, &ao}, {&b, &bo}, Operation::intersection);
  const PeerAssessment pa = assess_peer(out, &ref, input_resolution(a, b));
  ASSERT_EQ(pa.assessment.verdict, Verdict::wrong) << "CGAL fixed? then drop this case from the design notes";
  const PointCheck check = independent_point_check(a, b, Operation::intersection, ref, peer_cycles(out), out.unbounded);
  EXPECT_EQ(check.wrong, "other") << check.explanation;
}

TEST(Peers, CgalOutputIsRoundedToTheNearestDouble) {
  if (!is_peer("cgal_epeck")) GTEST_SKIP() << "built without CGAL";
  // The crossing (1/3, 2/3) of y = 2x with x + y = 1: neither coordinate is a double. CGAL's
  // exact output is rounded once, to nearest (issue 18: every rational through MPFR); the
  // double below 1/3 is the nearer one, and the tie rule of an interval midpoint would not
  // pick it.
  const std::string wa = "POLYGON((0 0,1 0,0 1,0 0))", wb = "POLYGON((0 0,1 2,-1 2,0 0))";
  const Polygon a = poly(wa), b = poly(wb);
  const MultiPolygon ao = read_wkt(wa), bo = read_wkt(wb);
  const PeerOutput out = run_peer("cgal_epeck", {&a, &ao}, {&b, &bo}, Operation::intersection);
  ASSERT_EQ(out.polygons.size(), 1u);
  ASSERT_EQ(out.exact_rings.size(), 1u);
  const Ring& ring = out.polygons[0].shell;
  const auto& exact = out.exact_rings[0][0];
  ASSERT_EQ(ring.size(), exact.size());
  bool crossing_seen = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    EXPECT_EQ(ring[i].x, nearest_double(exact[i].x)) << i;
    EXPECT_EQ(ring[i].y, nearest_double(exact[i].y)) << i;
    if (exact[i].x == mpq_class(1, 3)) {
      crossing_seen = true;
      EXPECT_EQ(ring[i].x, 1.0 / 3.0);
      EXPECT_EQ(ring[i].y, 2.0 / 3.0);
    }
  }
  EXPECT_TRUE(crossing_seen);
}

TEST(Peers, ClipperKeepsDoublesExactOnItsGrid) {
  if (!is_peer("clipper")) GTEST_SKIP() << "built without Clipper";
  // 0.6 is not a binary fraction, but the scale is a power of two and every double in the
  // largest coordinate's binade ([0.5, 1) here) lies on the grid: the square comes back
  // unchanged. (Smaller coordinates, e.g. 0.1, have finer ulps and may be rounded.)
  const std::string w = "POLYGON((0.5 0.5,0.7 0.5,0.7 0.6,0.5 0.6,0.5 0.5))";
  const Polygon a = poly(w);
  const MultiPolygon ao = read_wkt(w);
  const PeerOutput out = run_peer("clipper", {&a, &ao}, {&a, &ao}, Operation::union_);
  const ExactResult ref = exact_reference(a, a, Operation::union_, true, true);
  EXPECT_EQ(assess_peer(out, &ref, input_resolution(a, a)).assessment.verdict, Verdict::exact_area);
  EXPECT_GT(out.grid, 0.0);
  EXPECT_LE(out.grid, 0x1p-52);
}

ResultRow row(const std::string& kernel, Verdict v) {
  ResultRow r;
  r.case_index = 7;
  r.op = "union";
  r.kernel = kernel;
  r.verdict = v;
  return r;
}

TEST(Oracle, AgreementFollowsTheCgalRowOfTheSameRun) {
  std::vector<ResultRow> rows{row("exact", Verdict::exact_match), row("double", Verdict::exact_match),
                              row("cgal_epeck", Verdict::exact_area)};
  fill_oracle_agreement(rows);
  EXPECT_EQ(rows[0].oracle_agrees, std::optional<bool>(true));
  EXPECT_FALSE(rows[1].oracle_agrees);  // not an exact kernel
  rows = {row("exact", Verdict::exact_match), row("cgal_epeck", Verdict::wrong)};
  rows[1].message = "independent point check: cgal_epeck wrong (point (1, 2): ...)";
  fill_oracle_agreement(rows);
  EXPECT_EQ(rows[0].oracle_agrees, std::optional<bool>(false));
  EXPECT_NE(rows[0].message.find("cgal_epeck wrong"), std::string::npos);
  rows = {row("exact", Verdict::exact_match), row("cgal_epeck", Verdict::crash)};
  fill_oracle_agreement(rows);
  EXPECT_FALSE(rows[0].oracle_agrees);  // no result from CGAL: not counted either way
  // The columns survive the CSV.
  ResultRow r = row("exact", Verdict::exact_match);
  r.oracle_agrees = true;
  r.geos_valid = false;
  r.rounding_bound = 1.5e-12;
  const ResultRow back = parse_csv_row(to_csv(r));
  EXPECT_EQ(back.oracle_agrees, r.oracle_agrees);
  EXPECT_EQ(back.geos_valid, r.geos_valid);
  EXPECT_FALSE(back.exact_valid);
  EXPECT_EQ(back.rounding_bound, r.rounding_bound);
}

TEST(Statistics, AgreementTableGivesEveryShareItsInterval) {
  // Ten runs of one case each: exact always right, geos wrong on the first two; they agree
  // on 8 of 10. Issue 15: a 95% Wilson interval on every rate in the report.
  std::vector<ResultRow> rows;
  for (std::uint64_t c = 0; c < 10; ++c) {
    ResultRow k = row("exact", Verdict::exact_match);
    k.case_index = c;
    k.generator = "shared_edge";
    ResultRow p = k;
    p.kernel = "geos";
    p.verdict = c < 2 ? Verdict::wrong : Verdict::exact_area;
    rows.push_back(k);
    rows.push_back(p);
  }
  const std::string md = library_report(rows);
  const auto table = md.find("## Agreement between back ends");
  ASSERT_NE(table, std::string::npos) << md;
  EXPECT_NE(md.find("| exact |  | " + share_with_interval(8, 10) + " | 0 |", table), std::string::npos) << md.substr(table);
  EXPECT_NE(md.find("| geos | " + share_with_interval(8, 10) + " |  | 2 |", table), std::string::npos) << md.substr(table);
  EXPECT_EQ(share_with_interval(8, 10), "80% [49%–94%] of 10");
}

TEST(Outcome, OneScaleForKernelsAndPeers) {
  ResultRow r = row("double", Verdict::valid_different);
  r.symdiff_area = 1e-13;
  r.rounding_bound = 1e-12;
  EXPECT_EQ(outcome(r), Outcome::rounding_only);
  r.symdiff_area = 1e-11;
  EXPECT_EQ(outcome(r), Outcome::wrong);
  r.symdiff_area.reset();
  EXPECT_EQ(outcome(r), Outcome::unjudged);
  r.verdict = Verdict::error;
  r.message = "InvalidInput: polygon A ring 0 edge ... crosses ...";
  EXPECT_EQ(outcome(r), Outcome::refused);
  r.message = "KernelFailure: inconsistent";
  EXPECT_EQ(outcome(r), Outcome::exception);
  EXPECT_TRUE(is_failure(outcome(r)));
  EXPECT_FALSE(is_failure(outcome(row("geos", Verdict::rounding_only))));
  EXPECT_TRUE(is_failure(outcome(row("geos", Verdict::invalid_output))));
}

TEST(ExternalCases, ReaderNamesTheLineOfABadCase) {
  const fs::path f = fs::temp_directory_path() / ("mkbool_cases_" + std::to_string(::getpid()) + ".jsonl");
  std::ofstream(f) << R"J({"id":1,"op":"symdifference","a_wkt":"POLYGON((0 0,1 0,1 1,0 0))","b_wkt":"POLYGON EMPTY"})J" "\n\n"
                   << R"J({"id":"two","op":"union","a_wkt":"POLYGON((0 0,1 0,1 1,0 0))"})J" "\n";
  try {
    read_external_cases(f.string());
    ADD_FAILURE() << "a case without b_wkt was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(":3: missing \"b_wkt\""), std::string::npos) << e.what();
  }
  std::ofstream(f) << R"J({"id":1,"op":"symdifference","a_wkt":"POLYGON((0 0,1 0,1 1,0 0))","b_wkt":"POLYGON EMPTY"})J" "\n";
  const auto cases = read_external_cases(f.string());
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].id, "1");
  EXPECT_EQ(cases[0].op, "xor");
  fs::remove(f);
}

TEST(ExternalCases, EveryReportedCaseHasACitationAndASymptom) {
  const auto& corpus = reported_corpus();
  EXPECT_GE(corpus.size(), 100u);  // issue 15: at least 100 cases from public reports
  // A citation is owner/repository#number; the one exception is this project's own finding.
  const std::regex citation(R"(^[A-Za-z0-9_.-]+/[A-Za-z0-9_.-]+#[0-9]+$)");
  const std::set<std::string> ops{"intersection", "union", "difference", "xor"};
  for (const auto& c : corpus) {
    EXPECT_TRUE(std::regex_match(c.source, citation) || c.source == "shared/design/public-failure-reports.md")
        << c.id << ": " << c.source;
    EXPECT_TRUE(ops.count(c.op)) << c.id << ": " << c.op;
    EXPECT_FALSE(c.reported.empty()) << c.id;
    EXPECT_FALSE(c.library.empty()) << c.id;
    EXPECT_NO_THROW(read_wkt(c.a_wkt)) << c.id;
    EXPECT_NO_THROW(read_wkt(c.b_wkt)) << c.id;
  }
}

}  // namespace
}  // namespace mk::experiments
