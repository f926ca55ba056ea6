// paper-notes.md transcribes Tables 1-4 row by row; the code's constexpr tables must say the same.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "core/tables.hpp"

namespace mk {
namespace {

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string c;
  while (std::getline(ss, c, '|')) {
    const auto b = c.find_first_not_of(' ');
    const auto e = c.find_last_not_of(' ');
    out.push_back(b == std::string::npos ? "" : c.substr(b, e - b + 1));
  }
  if (!out.empty()) out.erase(out.begin());  // before the first '|'
  return out;
}

// Rows of the table that follows `#### Table n` in paper-notes.md.
std::vector<std::vector<std::string>> table_rows(int n) {
  std::ifstream in(std::string(MK_SOURCE_DIR) + "/paper-notes.md");
  std::string line;
  const std::string heading = "#### Table " + std::to_string(n);
  bool inside = false;
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    if (line.rfind("####", 0) == 0) {
      inside = line.rfind(heading, 0) == 0;
      continue;
    }
    if (!inside || line.rfind("| ", 0) != 0) continue;
    auto c = cells(line);
    if (c.empty() || c[0] == "operation") continue;
    rows.push_back(c);
  }
  return rows;
}

const std::map<std::string, Operation> kOp = {{"intersection", Operation::intersection},
                                              {"union", Operation::union_},
                                              {"difference", Operation::difference},
                                              {"xor", Operation::symmetric_difference}};
const std::map<std::string, PolygonType> kType = {{"island", PolygonType::island}, {"hole", PolygonType::hole}};
const std::map<std::string, Keep> kKeep = {{"as is", Keep::as_is}, {"reversed", Keep::reversed}, {"no", Keep::no}};

TEST(PaperNotes, Table1) {
  const auto rows = table_rows(1);
  ASSERT_EQ(rows.size(), 16u);
  for (const auto& r : rows) {
    const auto want = r[3] == "same" ? MutualOrientation::same : MutualOrientation::opposite;
    EXPECT_EQ(kTable1[op_index(kOp.at(r[0]))][type_index(kType.at(r[1]))][type_index(kType.at(r[2]))], want) << r[0];
  }
}

TEST(PaperNotes, Table2) {
  const auto rows = table_rows(2);
  ASSERT_EQ(rows.size(), 16u);
  for (const auto& r : rows) {
    const auto& cell = kTable2[op_index(kOp.at(r[0]))][type_index(kType.at(r[1]))][type_index(kType.at(r[2]))];
    EXPECT_EQ(cell.a.inside, kKeep.at(r[3])) << r[0] << " " << r[1] << " " << r[2];
    EXPECT_EQ(cell.a.outside, kKeep.at(r[4])) << r[0] << " " << r[1] << " " << r[2];
    EXPECT_EQ(cell.b.inside, kKeep.at(r[5])) << r[0] << " " << r[1] << " " << r[2];
    EXPECT_EQ(cell.b.outside, kKeep.at(r[6])) << r[0] << " " << r[1] << " " << r[2];
  }
}

TEST(PaperNotes, Table3) {
  const auto rows = table_rows(3);
  ASSERT_EQ(rows.size(), 32u);
  for (const auto& r : rows) {
    const int regular = r[3] == "regular" ? 1 : 0;
    const auto& cell = kTable3[regular][op_index(kOp.at(r[0]))][type_index(kType.at(r[1]))][type_index(kType.at(r[2]))];
    EXPECT_EQ(cell.same, std::stoi(r[4])) << r[0] << " " << r[3];
    EXPECT_EQ(cell.opposite, std::stoi(r[5])) << r[0] << " " << r[3];
  }
}

TEST(PaperNotes, Table4) {
  const auto rows = table_rows(4);
  ASSERT_EQ(rows.size(), 16u);
  for (const auto& r : rows) {
    EXPECT_EQ(kTable4[op_index(kOp.at(r[0]))][type_index(kType.at(r[1]))][type_index(kType.at(r[2]))],
              kType.at(r[3]));
  }
}

}  // namespace
}  // namespace mk
