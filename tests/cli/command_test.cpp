// The command's contract from issue 3: operations, input sources, output formats, --stats,
// atomic -o, unbounded results, every kernel, usage errors and exit codes.
// [MK89 §3.2] (procedure polygonoperation) [MK89 §2.3] (operations)
// Preconditions: the built mkbool (MK_CLI_EXE) and the library (for kernel_names()).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "api/mkbool.hpp"
#include "tests/cli/canonical_wkt.hpp"
#include "tests/cli/cli_support.hpp"

namespace mk::test {
namespace {

TEST(cliCommand, EveryOperation) {
  const std::pair<const char*, const char*> cases[] = {
      {"intersection", "POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))\n"},
      {"union", "POLYGON ((0 0, 2 0, 2 1, 3 1, 3 3, 1 3, 1 2, 0 2, 0 0))\n"},
      {"difference", "POLYGON ((0 0, 2 0, 2 1, 1 1, 1 2, 0 2, 0 0))\n"},
      {"xor", "MULTIPOLYGON (((0 0, 2 0, 2 1, 1 1, 1 2, 0 2, 0 0)), ((2 2, 2 1, 3 1, 3 3, 1 3, 1 2, 2 2)))\n"},
  };
  for (const auto& [op, expected] : cases) {
    const ProcessResult r = run_mkbool({op, square_a, square_b});
    EXPECT_EQ(r.exit_code, 0) << op << "\n" << describe(r);
    EXPECT_EQ(canonical_wkt(r.out), canonical_wkt(expected)) << op;
    EXPECT_EQ(r.err, "") << op;
  }
}

TEST(cliCommand, InputsFromFilesStandardInputAndInlineText) {
  TempDir dir;
  const std::string wkt = dir.write("a.wkt", square_a + "\n");
  const std::string geojson =
      dir.write("b.geojson", R"({"type":"Polygon","coordinates":[[[1,1],[3,1],[3,3],[1,3],[1,1]]]})");
  const std::string native = dir.write("b.json", R"({"type":"island","rings":[[[1,1],[3,1],[3,3],[1,3]]]})");
  const std::string sniffed = dir.write("b.txt", R"({"type":"Polygon","coordinates":[[[1,1],[3,1],[3,3],[1,3],[1,1]]]})");
  const std::string expected = "POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))\n";
  for (const auto& b : {geojson, native, sniffed, square_b}) {
    const ProcessResult r = run_mkbool({"intersection", wkt, b});
    EXPECT_EQ(r.exit_code, 0) << b << "\n" << describe(r);
    EXPECT_EQ(canonical_wkt(r.out), canonical_wkt(expected)) << b;
  }
  const ProcessResult from_stdin = run_mkbool({"intersection", "-", geojson}, square_a);
  EXPECT_EQ(from_stdin.exit_code, 0) << describe(from_stdin);
  EXPECT_EQ(canonical_wkt(from_stdin.out), canonical_wkt(expected));
  const ProcessResult json_stdin = run_mkbool({"intersection", wkt, "-"}, read_text(native));
  EXPECT_EQ(canonical_wkt(json_stdin.out), canonical_wkt(expected)) << describe(json_stdin);
}

TEST(cliCommand, TwoStandardInputsIsAUsageError) {
  const ProcessResult r = run_mkbool({"intersection", "-", "-"}, square_a);
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_EQ(r.err, "mkbool: error: A and B cannot both be standard input ('-')\n");
}

TEST(cliCommand, UsageErrorsExitTwo) {
  const std::vector<std::vector<std::string>> cases = {
      {},
      {"intersection", square_a},
      {"intersect", square_a, square_b},
      {"intersection", square_a, square_b, "--format", "kml"},
      {"intersection", square_a, square_b, "--a-type", "lake"},
      {"intersection", square_a, square_b, "--no-such-option"},
      {"intersection", square_a, square_b, "extra"},
      {"batch"},
      {"batch", "-", "--kernel", "magic"},
      {"batch", "-", "--format", "wkt"},
      {"intersection", square_a, square_b, "--kernel"},
      {"intersection", square_a, square_b, "-o"},
  };
  for (const auto& args : cases) {
    const ProcessResult r = run_mkbool(args);
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("mkbool: error: ", 0), 0u) << describe(r);
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line expected\n" << describe(r);  // issue 10, item 5
  }
}

TEST(cliCommand, SymdifferenceIsASynonymOfXor) {
  const ProcessResult sym = run_mkbool({"symdifference", square_a, square_b});
  const ProcessResult x = run_mkbool({"xor", square_a, square_b});
  ASSERT_EQ(sym.exit_code, 0) << describe(sym);
  EXPECT_EQ(sym.out, x.out);
  EXPECT_EQ(canonical_wkt(sym.out),
            canonical_wkt("MULTIPOLYGON (((0 0, 2 0, 2 1, 1 1, 1 2, 0 2, 0 0)), ((2 2, 2 1, 3 1, 3 3, 1 3, 1 2, 2 2)))"));
}

TEST(cliCommand, ZCoordinatesAndAltitudesAreDropped) {
  TempDir dir;
  const std::string b = dir.write(
      "b.geojson", R"({"type":"Polygon","coordinates":[[[1,1,10],[3,1,10],[3,3,12.5],[1,3,10],[1,1,10]]]})");
  for (const std::string a : {"POLYGON Z ((0 0 1,2 0 1,2 2 1,0 2 1,0 0 1))", "POLYGON ((0 0 1,2 0 1,2 2 1,0 2 1,0 0 1))",
                              "POLYGON ZM ((0 0 1 7,2 0 1 7,2 2 1 7,0 2 1 7,0 0 1 7))"}) {
    const ProcessResult r = run_mkbool({"intersection", a, b});
    EXPECT_EQ(r.exit_code, 0) << a << "\n" << describe(r);
    EXPECT_EQ(canonical_wkt(r.out), canonical_wkt("POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))")) << a;
  }
}

TEST(cliCommand, UnknownKernelExitsTwoAndListsTheKernels) {
  const ProcessResult r = run_mkbool({"intersection", square_a, square_b, "--kernel", "magic"});
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("mkbool: error: --kernel: unknown kernel 'magic' (built: exact, rational"), std::string::npos)
      << describe(r);
  const ProcessResult batch = run_mkbool({"batch", "-", "--kernel", "magic"}, "\n");
  EXPECT_EQ(batch.exit_code, 2) << describe(batch);
}

TEST(cliCommand, EveryKernelSucceeds) {
  for (const std::string_view k : kernel_names()) {
    const ProcessResult r = run_mkbool({"intersection", square_a, square_b, "--kernel", std::string(k), "--stats"});
    EXPECT_EQ(r.exit_code, 0) << k << "\n" << describe(r);
    const auto stats = nlohmann::json::parse(r.err);
    EXPECT_EQ(stats["kernel"], std::string(k));
    // Rounded kernels' results are data for the experiments, not asserted (STYLE.md).
    if (is_exact_kernel(k)) {
      EXPECT_EQ(canonical_wkt(r.out), canonical_wkt("POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))")) << k;
      EXPECT_EQ(stats["area_exact"], "1") << k;
    }
  }
}

TEST(cliCommand, HelpAndVersion) {
  const ProcessResult help = run_mkbool({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  for (const char* s : {"mkbool OP A B", "mkbool batch FILE.jsonl", "--kernel", "--non-regular", "--a-type", "--b-type",
                        "--format", "--stats", "Exit codes"}) {
    EXPECT_NE(help.out.find(s), std::string::npos) << s;
  }
  const ProcessResult batch_help = run_mkbool({"batch", "--help"});
  EXPECT_EQ(batch_help.exit_code, 0);
  EXPECT_NE(batch_help.out.find("symdifference"), std::string::npos);
  const ProcessResult version = run_mkbool({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out, std::string("mkbool ") + MK_PROJECT_VERSION + "\n");
}

TEST(cliCommand, StatsIsOneJsonLineWithTheDocumentedKeys) {
  const ProcessResult r = run_mkbool({"intersection", square_a, square_b, "--stats"});
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  ASSERT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line expected: " << r.err;
  const auto stats = nlohmann::json::parse(r.err);
  for (const char* key :
       {"kernel", "op_ns", "vertices_in", "crossings", "vertices_out", "rounded_valid", "area", "area_beyond_double",
        "area_exact"}) {
    EXPECT_TRUE(stats.contains(key)) << key;
  }
  EXPECT_EQ(stats["kernel"], std::string(default_kernel()));
  EXPECT_TRUE(stats["op_ns"].is_number_integer());
  EXPECT_GT(stats["op_ns"].get<long long>(), 0);
  EXPECT_EQ(stats["vertices_in"], 8);
  EXPECT_EQ(stats["crossings"], 2);
  EXPECT_EQ(stats["vertices_out"], 4);
  EXPECT_EQ(stats["rounded_valid"], true);
  EXPECT_EQ(stats["area"], 1.0);
  EXPECT_EQ(stats["area_beyond_double"], false);
  EXPECT_EQ(stats["area_exact"], "1");

  const ProcessResult inexact = run_mkbool({"intersection", square_a, square_b, "--stats", "--kernel", "double"});
  const auto s2 = nlohmann::json::parse(inexact.err);
  EXPECT_EQ(s2["rounded_valid"], true);  // the exact check of the doubles it wrote, for every kernel
  EXPECT_TRUE(s2["area_exact"].is_null());
}

TEST(cliCommand, StatsGiveAnExactRationalArea) {
  // The edges (0 0)-(1 1) and (3 0)-(0 1) cross at (3/4, 3/4), and (1 0)-(1 1) meets the
  // latter at (1, 2/3): a quadrilateral of area 9/32 + 19/96 = 11/24.
  const ProcessResult r =
      run_mkbool({"intersection", "POLYGON((0 0,3 0,0 1,0 0))", "POLYGON((0 0,1 0,1 1,0 0))", "--stats"});
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto stats = nlohmann::json::parse(r.err);
  EXPECT_EQ(stats["area_exact"], "11/24");
  EXPECT_EQ(stats["area"], 11.0 / 24.0);  // the nearest double: IEEE division rounds correctly
}

TEST(cliCommand, GeoJsonOutput) {
  const ProcessResult r = run_mkbool({"intersection", square_a, square_b, "--format", "geojson"});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["type"], "Polygon");
  EXPECT_EQ(j["coordinates"][0].size(), 5u);
}

TEST(cliCommand, NativeJsonOutputHasExactCoordinatesAndValidity) {
  const ProcessResult r = run_mkbool(
      {"intersection", "POLYGON((0 0,3 0,0 1,0 0))", "POLYGON((0 0,1 0,1 1,0 0))", "--format", "json"});
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["kernel"], std::string(default_kernel()));
  EXPECT_EQ(j["unbounded"], false);
  EXPECT_EQ(j["rounded_valid"], true);
  ASSERT_EQ(j["polygons"].size(), 1u);
  EXPECT_EQ(j["polygons"][0]["type"], "island");
  EXPECT_NE(r.out.find("[\"3/4\",\"3/4\"]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[\"1\",\"2/3\"]"), std::string::npos) << r.out;
}

TEST(cliCommand, HoleTypesFromTheCommandLine) {
  // A as a hole: B minus the square A's interior... as the intersection of B with A's complement.
  const ProcessResult r = run_mkbool({"intersection", square_a, square_b, "--a-type", "hole"});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(canonical_wkt(r.out), canonical_wkt("POLYGON ((2 1, 3 1, 3 3, 1 3, 1 2, 2 2, 2 1))"));
}

TEST(cliCommand, UnboundedResultAsWktOrGeoJsonSuggestsJson) {
  for (const char* format : {"wkt", "geojson"}) {
    TempDir dir;
    const std::string out = dir.file("out.txt");
    const ProcessResult r = run_mkbool(
        {"union", square_a, square_b, "--a-type", "hole", "--b-type", "hole", "--format", format, "-o", out});
    EXPECT_EQ(r.exit_code, 1) << describe(r);
    EXPECT_NE(r.err.find("is unbounded"), std::string::npos) << describe(r);
    EXPECT_NE(r.err.find("use --format json"), std::string::npos) << describe(r);
    EXPECT_TRUE(dir.entries().empty()) << "no output file on failure";
  }
  const ProcessResult json =
      run_mkbool({"union", square_a, square_b, "--a-type", "hole", "--b-type", "hole", "--format", "json"});
  EXPECT_EQ(json.exit_code, 0) << describe(json);
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["unbounded"], true);
  EXPECT_EQ(j["polygons"][0]["type"], "hole");
}

TEST(cliCommand, SvgOutputIsAnSvgDocument) {
  const ProcessResult r = run_mkbool({"xor", square_a, square_b, "--format", "svg"});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.out.find("<svg"), std::string::npos);
  EXPECT_NE(r.out.find("</svg>"), std::string::npos);
  const ProcessResult unbounded = run_mkbool({"union", square_a, square_b, "--a-type", "hole", "--format", "svg"});
  EXPECT_EQ(unbounded.exit_code, 0) << describe(unbounded);
  EXPECT_NE(unbounded.out.find("<svg"), std::string::npos);
}

TEST(cliCommand, NonRegularKeepsDanglingEdgesAndPoints) {
  const ProcessResult edge =
      run_mkbool({"intersection", square_a, "POLYGON((2 0,4 0,4 2,2 2,2 0))", "--non-regular"});
  EXPECT_EQ(edge.out, "GEOMETRYCOLLECTION (LINESTRING (2 0, 2 2))\n") << describe(edge);
  const ProcessResult regular = run_mkbool({"intersection", square_a, "POLYGON((2 0,4 0,4 2,2 2,2 0))"});
  EXPECT_EQ(regular.out, "POLYGON EMPTY\n") << describe(regular);
}

TEST(cliCommand, OutputFileIsWrittenWhole) {
  TempDir dir;
  const std::string out = dir.file("result.wkt");
  const ProcessResult r = run_mkbool({"intersection", square_a, square_b, "-o", out});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(canonical_wkt(read_text(out)), canonical_wkt("POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"result.wkt"}) << "no temporary file left";
}

TEST(cliCommand, FailingRunLeavesNoOutputFile) {
  TempDir dir;
  const std::string out = dir.file("result.wkt");
  const ProcessResult bad = run_mkbool({"intersection", "POLYGON((0 0,1 0,0 1,1 1,0 0))", square_b, "-o", out});
  EXPECT_EQ(bad.exit_code, 3) << describe(bad);
  EXPECT_TRUE(dir.entries().empty());
  // An existing file survives a failed run unchanged.
  dir.write("result.wkt", "old\n");
  const ProcessResult again = run_mkbool({"intersection", "POLYGON((0 0,nan 0,0 1,0 0))", square_b, "-o", out});
  EXPECT_EQ(again.exit_code, 3) << describe(again);
  EXPECT_EQ(read_text(out), "old\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"result.wkt"});
}

TEST(cliCommand, UnwritableOutputExitsOne) {
  TempDir dir;
  const ProcessResult r = run_mkbool({"intersection", square_a, square_b, "-o", dir.file("no/such/dir/out.wkt")});
  EXPECT_EQ(r.exit_code, 1) << describe(r);
  EXPECT_NE(r.err.find("cannot create output file"), std::string::npos) << describe(r);
  // A directory as the target: the temporary file is written, the rename fails, nothing stays.
  std::filesystem::create_directory(dir.file("taken"));
  const ProcessResult onto_dir = run_mkbool({"intersection", square_a, square_b, "-o", dir.file("taken")});
  EXPECT_EQ(onto_dir.exit_code, 1) << describe(onto_dir);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken"});
}

// A full device (/dev/full) behind the result or behind --stats: exit 1, never 0 with the
// output or the asked-for statistics lost. With --stats lost, the result is still written.
TEST(cliCommand, FullOutputOrFullStandardErrorExitsOne) {
  if (!std::filesystem::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  const std::string command = "'" + mkbool_exe() + "' intersection '" + square_a + "' '" + square_b + "'";
  const ProcessResult to_file = run_mkbool({"intersection", square_a, square_b, "-o", "/dev/full"});
  EXPECT_EQ(to_file.exit_code, 1) << describe(to_file);
  EXPECT_NE(to_file.err.find("No space left on device"), std::string::npos) << describe(to_file);
  const ProcessResult to_stdout = run_process({"/bin/sh", "-c", command + " > /dev/full"});
  EXPECT_EQ(to_stdout.exit_code, 1) << describe(to_stdout);
  const ProcessResult stats = run_process({"/bin/sh", "-c", command + " --stats 2> /dev/full"});
  EXPECT_EQ(stats.exit_code, 1) << describe(stats);
  EXPECT_EQ(canonical_wkt(stats.out), canonical_wkt("POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))")) << describe(stats);
  // Help and version too: exit 1 when they cannot be written, 0 when they can.
  for (const std::string flag : {"--help", "--version", "batch --help", "union-all --help"}) {
    const ProcessResult full = run_process({"/bin/sh", "-c", "'" + mkbool_exe() + "' " + flag + " > /dev/full"});
    EXPECT_EQ(full.exit_code, 1) << flag << " " << describe(full);
    const ProcessResult ok = run_process({"/bin/sh", "-c", "'" + mkbool_exe() + "' " + flag + " > /dev/null"});
    EXPECT_EQ(ok.exit_code, 0) << flag << " " << describe(ok);
  }
}

TEST(cliCommand, DeviceTargetIsWrittenInPlace) {
  // Renaming a temporary file over /dev/null would replace the device.
  const ProcessResult r = run_mkbool({"intersection", square_a, square_b, "-o", "/dev/null"});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}

}  // namespace
}  // namespace mk::test

namespace mk::test {
namespace {

TEST(cliCommand, MillionLevelNestingInIgnoredMembersIsRead) {
  // issue 10, item 2: the command reads JSON of any depth without recursion (batch did not).
  constexpr std::size_t n = 1'000'000;
  const std::string deep = std::string(n, '[') + std::string(n, ']');
  TempDir dir;
  const std::string geojson = dir.write(
      "a.geojson", R"({"type":"Feature","properties":{"x":)" + deep +
                       R"(},"geometry":{"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,2],[0,0]]]}})");
  const std::string native = dir.write("b.json", R"({"note":)" + deep + R"(,"rings":[[[1,1],[3,1],[3,3],[1,3]]]})");
  const ProcessResult r = run_mkbool({"intersection", geojson, square_b});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(canonical_wkt(r.out), canonical_wkt("POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))"));
  // Native JSON has no ignored members: the deep one is refused by name, cleanly.
  const ProcessResult strict = run_mkbool({"intersection", geojson, native});
  EXPECT_EQ(strict.exit_code, 3) << describe(strict);
  EXPECT_NE(strict.err.find("unknown member \"note\""), std::string::npos) << describe(strict);
  const ProcessResult unclosed = run_mkbool({"intersection", "-", square_b}, std::string(n, '['));
  EXPECT_EQ(unclosed.exit_code, 3) << describe(unclosed);
}

}  // namespace
}  // namespace mk::test
