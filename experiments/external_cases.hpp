// Cases from outside the harness: the `reported` corpus (inputs of public issue reports of
// polygon Boolean libraries, experiments/reported/*.jsonl) and the user's own pairs
// (`mkbool-experiment run --cases FILE.jsonl`, generator `cases`), both in the batch
// format of `mkbool batch`: one JSON object a line with "id", "op", "a_wkt", "b_wkt".
// [BRIEF §5] (experiments) [OGC06-103 §7] (WKT)
// Preconditions: a corpus line that is not JSON or lacks a member fails loading with its
// file and line; WKT that mkbool cannot read becomes the case's `refused` verdict.
#pragma once

#include <string>
#include <vector>

#include "experiments/case.hpp"

namespace mk::experiments {

struct ExternalCase {
  std::string id;        // unique in its corpus; the CaseSpec's variant
  std::string op;        // the operation the report (or the user) names
  std::string a_wkt, b_wkt;
  std::string source;    // reported: "owner/repository#number"
  std::string library;   // reported: the library the report is about
  std::string reported;  // reported: what the report says went wrong
  std::string file;      // where it was read, with its line: "geos.jsonl:12"
};

// Reads a JSON Lines file of cases (blank lines skipped). Throws std::runtime_error naming
// the file and line.
std::vector<ExternalCase> read_external_cases(const std::string& path);

// The reported corpus: every experiments/reported/*.jsonl in file-name order ($MK_REPORTED_DIR
// overrides the directory). Loaded once.
const std::vector<ExternalCase>& reported_corpus();
std::string reported_dir();

// The user's cases for generator `cases` (set by `run --cases FILE` before the sweep).
void set_user_cases(const std::string& path);
const std::vector<ExternalCase>& user_cases();

// The case of a `reported` or `cases` spec (variant = id): inputs parsed from WKT with their
// OGC structure kept. Throws mk::InvalidInput when mkbool cannot read the WKT.
PolygonPair reported(const CaseSpec& spec);
PolygonPair cases(const CaseSpec& spec);
Case make_external_case(const CaseSpec& spec);

}  // namespace mk::experiments
