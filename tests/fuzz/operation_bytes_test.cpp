// The whole-operation fuzz target's byte format: generator cases survive encode/decode
// exactly, any bytes decode to finite coordinates, and the seed tool writes decodable seeds
// and refuses bad arguments (exit 2, one line). [MK89 §2.2] [BRIEF §5]
// Preconditions: MK_FUZZ_SEED_EXE names the built fuzz_seed_corpus.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "experiments/generators.hpp"
#include "fuzz/operation_bytes.hpp"
#include "tests/cli/run_process.hpp"

namespace mk::fuzz {
namespace {

namespace fs = std::filesystem;

DecodedCase decode(const std::string& bytes) {
  return decode_case(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

TEST(fuzzOperationBytes, GeneratorCasesSurviveEncodeAndDecode) {
  experiments::PlanOptions plan;
  plan.level = experiments::SweepLevel::quick;
  int checked = 0;
  for (const auto& spec : experiments::plan_sweep(plan)) {
    const experiments::Case c = experiments::make_case(spec);
    if (c.size() > 64 || c.a.rings.size() > 4 || c.b.rings.size() > 4) continue;
    bool small_rings = true;
    for (const Polygon* p : {&c.a, &c.b}) {
      for (const Ring& r : p->rings) small_rings = small_rings && !r.empty() && r.size() <= 32;
    }
    if (!small_rings) continue;
    SCOPED_TRACE(spec.stem());
    const DecodedCase d = decode(encode_case(c.a, c.b, Operation::difference, false));
    EXPECT_EQ(d.a.rings, c.a.rings);
    EXPECT_EQ(d.b.rings, c.b.rings);
    EXPECT_EQ(d.a.type, c.a.type);
    EXPECT_EQ(d.b.type, c.b.type);
    EXPECT_EQ(d.op, Operation::difference);
    EXPECT_FALSE(d.regular);
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(fuzzOperationBytes, AnyBytesDecodeToFiniteCoordinates) {
  const std::uint64_t seed = 7;
  std::mt19937_64 rng(seed);
  std::printf("fuzzOperationBytes random bytes: seed %llu\n", static_cast<unsigned long long>(seed));
  for (int n = 0; n < 2000; ++n) {
    std::string bytes(rng() % 300, '\0');
    for (char& b : bytes) b = static_cast<char>(rng());
    const DecodedCase d = decode(bytes);
    for (const Polygon* p : {&d.a, &d.b}) {
      EXPECT_LE(p->rings.size(), 4u);
      for (const Ring& r : p->rings) {
        EXPECT_LE(r.size(), 32u);
        for (const Point& q : r) EXPECT_TRUE(std::isfinite(q.x) && std::isfinite(q.y));
      }
    }
  }
}

TEST(fuzzOperationBytes, SeedToolWritesSeedsAndRefusesBadArguments) {
  const fs::path dir = fs::temp_directory_path() / ("mkbool-fuzz-seeds-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const test::ProcessResult r = test::run_process({MK_FUZZ_SEED_EXE, dir.string(), "1"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  int seeds = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    std::ifstream in(e.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const DecodedCase d = decode(bytes);
    EXPECT_FALSE(d.a.rings.empty() && d.b.rings.empty()) << e.path();
    ++seeds;
  }
  EXPECT_GT(seeds, 20);
  fs::remove_all(dir);
  for (const std::vector<std::string>& args : {std::vector<std::string>{MK_FUZZ_SEED_EXE},
                                               {MK_FUZZ_SEED_EXE, dir.string(), "0"},
                                               {MK_FUZZ_SEED_EXE, dir.string(), "x"},
                                               {MK_FUZZ_SEED_EXE, "a", "1", "b"}}) {
    const test::ProcessResult bad = test::run_process(args);
    EXPECT_EQ(bad.exit_code, 2) << bad.err;
    EXPECT_EQ(bad.err.find('\n'), bad.err.size() - 1) << bad.err;
  }
}

}  // namespace
}  // namespace mk::fuzz
