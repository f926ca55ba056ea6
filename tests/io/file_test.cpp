// Tests of read_file: contents, empty files, and the errors for unusable paths.
// [OGC06-103 §7] [RFC7946]
// Preconditions: a writable temporary directory.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/file.hpp"
#include "test_util.hpp"

namespace mk {
namespace {

namespace fs = std::filesystem;

class ioFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("mkbool_io_file_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  fs::path dir_;
};

TEST_F(ioFile, ReadsContentsExactly) {
  const std::string content = std::string("POLYGON EMPTY\n\0\xff", 16);
  EXPECT_EQ(read_file(write("a.wkt", content)), content);
}

TEST_F(ioFile, ReadsLargeFiles) {
  const std::string content(3 << 20, 'x');
  EXPECT_EQ(read_file(write("big.wkt", content)).size(), content.size());
}

TEST_F(ioFile, EmptyFileGivesEmptyString) {
  const std::string path = write("empty.wkt", "");
  EXPECT_EQ(read_file(path), "");
  EXPECT_EQ(empty_input_message(path), std::string(1, '\'') + path +
                                           "' is empty: expected a polygon in WKT, GeoJSON or "
                                           "native JSON (an empty polygon is written POLYGON EMPTY)");
}

TEST_F(ioFile, MissingFileIsAnError) {
  const std::string path = (dir_ / "missing.wkt").string();
  EXPECT_TRUE(test::rejects([&] { read_file(path); },
                            std::string("cannot open '") + path + "': No such file or directory"));
}

TEST_F(ioFile, DirectoryIsAnError) {
  const std::string expected = dir_.string() + "' is a directory, not a file";
  EXPECT_TRUE(test::rejects([&] { read_file(dir_.string()); }, expected));
}

TEST_F(ioFile, EmptyPathIsAnError) {
  EXPECT_TRUE(test::rejects([] { read_file(""); }, "no input file given (the path is empty)"));
}

}  // namespace
}  // namespace mk
