// The reported corpus and the user's cases, read from JSON Lines. [BRIEF §5]
// Preconditions: see external_cases.hpp.
#include "experiments/external_cases.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "io/wkt.hpp"

#ifndef MK_EXPERIMENTS_SOURCE_DIR
#define MK_EXPERIMENTS_SOURCE_DIR "experiments"
#endif

namespace mk::experiments {

namespace fs = std::filesystem;

std::vector<ExternalCase> read_external_cases(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<ExternalCase> out;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = fs::path(path).filename().string() + ":" + std::to_string(n);
    try {
      const auto j = nlohmann::json::parse(line);
      const auto text = [&](const char* key, bool required) -> std::string {
        if (!j.contains(key)) {
          if (required) throw std::runtime_error(std::string("missing \"") + key + "\"");
          return {};
        }
        const auto& v = j.at(key);
        return v.is_string() ? v.get<std::string>() : v.dump();
      };
      ExternalCase c;
      c.id = j.contains("id") ? text("id", true) : "line" + std::to_string(n);
      c.op = text("op", true);
      if (c.op == "symdifference") c.op = "xor";
      c.a_wkt = text("a_wkt", true);
      c.b_wkt = text("b_wkt", true);
      c.source = text("source", false);
      c.library = text("library", false);
      c.reported = text("reported", false);
      c.file = where;
      for (char& ch : c.id) {
        if (ch == ',' || ch == '"' || ch == ' ' || ch == '/') ch = '_';  // CSV and file-name safe
      }
      if (std::any_of(out.begin(), out.end(), [&](const ExternalCase& o) { return o.id == c.id; })) {
        throw std::runtime_error("id '" + c.id + "' appears twice");
      }
      out.push_back(std::move(c));
    } catch (const std::exception& e) {
      throw std::runtime_error(where + ": " + e.what());
    }
  }
  return out;
}

std::string reported_dir() {
  if (const char* env = std::getenv("MK_REPORTED_DIR")) return env;
  return std::string(MK_EXPERIMENTS_SOURCE_DIR) + "/reported";
}

const std::vector<ExternalCase>& reported_corpus() {
  static const std::vector<ExternalCase> corpus = [] {
    std::vector<std::string> files;
    if (fs::is_directory(reported_dir())) {
      for (const auto& e : fs::directory_iterator(reported_dir())) {
        if (e.path().extension() == ".jsonl") files.push_back(e.path().string());
      }
    }
    std::sort(files.begin(), files.end());
    std::vector<ExternalCase> all;
    for (const auto& f : files) {
      for (auto& c : read_external_cases(f)) {
        if (std::any_of(all.begin(), all.end(), [&](const ExternalCase& o) { return o.id == c.id; })) {
          throw std::runtime_error(c.file + ": id '" + c.id + "' appears in another corpus file");
        }
        all.push_back(std::move(c));
      }
    }
    return all;
  }();
  return corpus;
}

namespace {

std::vector<ExternalCase>& user_case_store() {
  static std::vector<ExternalCase> store;
  return store;
}

const ExternalCase& find_case(const std::vector<ExternalCase>& corpus, const CaseSpec& spec) {
  for (const auto& c : corpus) {
    if (c.id == spec.variant) return c;
  }
  throw std::invalid_argument("generator " + spec.generator + ": no case with id '" + spec.variant + "'");
}

}  // namespace

void set_user_cases(const std::string& path) { user_case_store() = read_external_cases(path); }
const std::vector<ExternalCase>& user_cases() { return user_case_store(); }

Case make_external_case(const CaseSpec& spec) {
  const ExternalCase& c = find_case(spec.generator == "reported" ? reported_corpus() : user_cases(), spec);
  Case out;
  out.spec = spec;
  out.a_ogc = read_wkt(c.a_wkt);
  out.b_ogc = read_wkt(c.b_wkt);
  out.a = to_polygon(*out.a_ogc);
  out.b = to_polygon(*out.b_ogc);
  return out;
}

PolygonPair reported(const CaseSpec& spec) {
  Case c = make_external_case(spec);
  return {std::move(c.a), std::move(c.b)};
}

PolygonPair cases(const CaseSpec& spec) { return reported(spec); }

}  // namespace mk::experiments
