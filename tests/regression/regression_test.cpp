// Replays every regression case in tests/regression/cases/: each failure an experiment or a
// test found, kept as a named case (STYLE.md). A case names one operation; all eight
// (operation, regular or not) run, each with both exact kernels, and are checked against
// CGAL Epeck and the membership oracle (tests/oracle/checks.hpp).
// To add one: copy a file the harness wrote (DIR/regression/<generator>_<seed>.wkt, see
// experiments/README.md) into tests/regression/cases/; it is picked up at the next run.
// Fill-rule and set cases (a fill_rule line; union_all, intersection_all) are checked by
// their exact area against CGAL's arrangement of every ring (tests/oracle/cgal_winding.hpp).
// [BRIEF §5] (every failure becomes a regression case) [BRIEF §1]
// Preconditions: the cases are in the format of mk::experiments::read_regression_case.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

#include "api/mkbool.hpp"
#include "experiments/artefacts.hpp"
#include "tests/oracle/cgal_winding.hpp"
#include "tests/oracle/checks.hpp"
#include "tests/oracle/families.hpp"

namespace mk::oracle {
namespace {

namespace fs = std::filesystem;

const fs::path kCases = fs::path(MK_SOURCE_DIR) / "tests" / "regression" / "cases";

std::vector<fs::path> case_files() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(kCases)) {
    if (e.path().extension() == ".wkt") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Regression, EveryCaseFileIsNamedAfterItsGeneratorAndReadable) {
  const auto files = case_files();
  ASSERT_FALSE(files.empty()) << "no regression cases in " << kCases;
  // <generator>_<seed or variant>[_<op>[_nonregular]].wkt, as the harness names them.
  const std::regex name("[a-z0-9]+(_[a-z0-9]+)*_[A-Za-z0-9-]+(_(intersection|union|difference|xor)(_nonregular)?)?");
  for (const auto& f : files) {
    EXPECT_TRUE(std::regex_match(f.stem().string(), name)) << f.filename();
    std::ifstream in(f);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NO_THROW(experiments::read_regression_case(text.str())) << f.filename();
  }
}

QRing exact_ring(const Ring& r) {
  QRing q;
  for (const Point& p : r) q.push_back({Q(p.x), Q(p.y)});
  return q;
}

// Fill-rule and set cases (experiments/README.md, "Set cases"): the exact area CGAL's
// arrangement of every ring gives, the faces selected by the winding numbers of each
// operand's rings (A and B; a set's rings together for union_all, each part on its own for
// intersection_all, every part as fill_rule_polygon orients it) under the case's rule.
Q arrangement_area(const experiments::RegressionCase& c) {
  const FillRule rule = c.fill_rule.value_or(FillRule::union_);
  std::vector<std::vector<Ring>> groups;
  if (!c.parts) {
    groups = {c.a.rings, c.b.rings};
  } else if (c.op == Operation::union_) {
    groups = {fill_rule_polygon(*c.parts, rule).rings};
  } else {
    for (const OgcPolygon& part : *c.parts) groups.push_back(fill_rule_polygon(MultiPolygon{part}, rule).rings);
  }
  std::vector<std::vector<QRing>> operands;
  std::vector<std::size_t> group_of;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (const Ring& r : groups[g]) {
      operands.push_back({exact_ring(r)});
      group_of.push_back(g);
    }
  }
  const WindingArrangement arr(operands);
  EXPECT_EQ(arr.inconsistency(), "");
  return arr.area(arr.select([&](const std::vector<int>& w) {
    std::vector<int> sum(groups.size(), 0);
    for (std::size_t i = 0; i < w.size(); ++i) sum[group_of[i]] += w[i];
    std::vector<bool> in;
    for (const int v : sum) in.push_back(is_filled(rule, v));
    if (!c.parts) return face_in_result(c.op, in[0], in[1]);
    const bool in_all = std::find(in.begin(), in.end(), false) == in.end();
    return c.op == Operation::union_ ? in[0] : in_all;  // union_all: one group of all rings
  }));
}

// The case's operation, regular and not, with every exact kernel: its exact area (the
// regular part's) is the arrangement's.
void check_by_arrangement(const experiments::RegressionCase& c, const std::string& name) {
  const Q expected = arrangement_area(c);
  std::cout << name << ": area about " << expected.get_d() << " by CGAL's arrangement, compared exactly\n";
  for (const auto k : kernel_names()) {
    if (!is_exact_kernel(k)) continue;
    for (const bool regular : {true, false}) {
      BooleanOptions o{c.op, regular, std::string(k)};
      o.area_exact = true;
      const BooleanOutput r = experiments::replay_regression_case(c, o);
      EXPECT_EQ(r.stats.area_exact.value_or("?"), expected.get_str())
          << name << ": " << k << (regular ? " regular" : " non-regular");
    }
  }
}

TEST(Regression, EveryCaseAgreesWithCgalEpeckAndTheMembershipOracle) {
  Tally tally;
  for (const auto& f : case_files()) {
    std::ifstream in(f);
    std::stringstream text;
    text << in.rdbuf();
    const experiments::RegressionCase c = experiments::read_regression_case(text.str());
    if (c.fill_rule || c.parts) {
      check_by_arrangement(c, f.filename().string());
      continue;
    }
    const References refs = References::of(c.a, c.b);
    std::mt19937_64 rng(1);
    // The case's own operation first, then the other seven.
    std::vector<std::pair<Operation, bool>> runs{{c.op, c.regular}};
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                               Operation::symmetric_difference}) {
      for (const bool regular : {true, false}) {
        if (op != c.op || regular != c.regular) runs.push_back({op, regular});
      }
    }
    for (const auto& [op, regular] : runs) {
      for (const auto ef : {EfOrganisation::hash, EfOrganisation::sorted}) {
        const std::string what = f.filename().string() + ": " + std::string(operation_name(op)) +
                                 (regular ? " regular" : " non-regular") + "\n  A " + describe(c.a) + "\n  B " +
                                 describe(c.b);
        EXPECT_EQ(check_operation(c.a, c.b, refs, Options{op, regular, ef, PairSearch::sweep}, rng, tally, what), "")
            << what;
      }
    }
  }
  std::cout << tally.operations << " operations replayed; CGAL faults shown by the oracle: " << tally.cgal_faults
            << "\n";
  EXPECT_GT(tally.operations, 0);
}

}  // namespace
}  // namespace mk::oracle
