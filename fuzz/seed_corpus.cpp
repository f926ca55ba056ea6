// fuzz_seed_corpus DIR [MAX]: writes seeds for the whole-operation fuzz target
// (fuzz/operation_bytes.hpp) from the experiment generators: for every generator and variant
// of the quick sweep, its first cases with at most 64 input vertices, each under a rotating
// operation and regularity. fuzz/run.sh seeds its scratch corpus with them when the tool is
// built; fuzz/corpus/fuzz_operation holds a small committed selection (one per variant).
// [MK89 §2.2] [BRIEF §5] (the generators)
// Preconditions: DIR exists and is writable.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

#include "experiments/generators.hpp"
#include "fuzz/operation_bytes.hpp"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::cerr << "fuzz_seed_corpus: error: expected DIR [MAX PER VARIANT] (usage: fuzz_seed_corpus DIR [MAX])\n";
    return 2;
  }
  const std::string dir = argv[1];
  int per_variant = 4;
  if (argc == 3) {
    try {
      std::size_t end = 0;
      per_variant = std::stoi(argv[2], &end);
      if (end != std::string(argv[2]).size() || per_variant < 1) throw std::invalid_argument("");
    } catch (const std::exception&) {
      std::cerr << "fuzz_seed_corpus: error: MAX must be a whole number of at least 1, got '" << argv[2] << "'\n";
      return 2;
    }
  }
  mk::experiments::PlanOptions plan;
  plan.level = mk::experiments::SweepLevel::quick;
  std::map<std::string, int> written;
  int count = 0;
  for (const auto& spec : mk::experiments::plan_sweep(plan)) {
    const std::string key = spec.generator + "_" + spec.variant;
    if (written[key] >= per_variant) continue;
    const mk::experiments::Case c = mk::experiments::make_case(spec);
    if (c.size() > 64) continue;
    const int k = written[key]++;
    const std::string bytes =
        mk::fuzz::encode_case(c.a, c.b, static_cast<mk::Operation>(count % 4), count % 8 < 4);
    const std::string path = dir + "/" + key + "_" + std::to_string(k);
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    if (!out) {
      std::cerr << "fuzz_seed_corpus: error: cannot write " << path << "\n";
      return 1;
    }
    ++count;
  }
  std::cout << "fuzz_seed_corpus: " << count << " seeds in " << dir << "\n";
  return 0;
}
