// Replays every regression case in tests/regression/cases/: each failure an experiment or a
// test found, kept as a named case (STYLE.md). A case names one operation; all eight
// (operation, regular or not) run, each with both exact kernels, and are checked against
// CGAL Epeck and the membership oracle (tests/oracle/checks.hpp).
// To add one: copy a file the harness wrote (DIR/regression/<generator>_<seed>.wkt, see
// experiments/README.md) into tests/regression/cases/; it is picked up at the next run.
// [BRIEF §5] (every failure becomes a regression case) [BRIEF §1]
// Preconditions: the cases are in the format of mk::experiments::read_regression_case.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

#include "experiments/artefacts.hpp"
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

TEST(Regression, EveryCaseAgreesWithCgalEpeckAndTheMembershipOracle) {
  Tally tally;
  for (const auto& f : case_files()) {
    std::ifstream in(f);
    std::stringstream text;
    text << in.rdbuf();
    const experiments::RegressionCase c = experiments::read_regression_case(text.str());
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
