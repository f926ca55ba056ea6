// Tests of the peer back ends and their verdicts: Wilson intervals, OGC forms and the
// exact OGC check, each peer on a case it must get exactly right, the known CGAL fault with
// the independent point check, the oracle_agrees column, the outcome scale, and the corpus
// reader. [BRIEF §5] [OGC06-103 §6.1.11]
// Preconditions: peers present as built (each test covers the peers this build has).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

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
