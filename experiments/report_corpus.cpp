// The report's tables of external cases: the reported corpus (with each report's citation
// and symptom, and how many of the cases reported against a library its counterpart here
// still fails) and the user's cases. [BRIEF §5]
// Preconditions: rows from run_sweep; the corpus files as they were when the sweep ran.
#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/external_cases.hpp"
#include "experiments/report_library.hpp"
#include "experiments/statistics.hpp"

namespace mk::experiments {

namespace {

std::string short_outcome(Outcome o) {
  switch (o) {
    case Outcome::exact: return "exact";
    case Outcome::rounding_only: return "≈";
    case Outcome::wrong: return "**wrong**";
    case Outcome::invalid_output: return "**invalid**";
    case Outcome::exception: return "**exception**";
    case Outcome::crash: return "**crash**";
    case Outcome::timeout: return "**timeout**";
    case Outcome::refused: return "refused";
    case Outcome::unjudged: return "valid, unjudged";
    case Outcome::unsupported: return "–";
  }
  return "?";
}

}  // namespace

std::string corpus_report(const std::vector<ResultRow>& rows, const std::vector<std::string>& backends) {
  std::ostringstream md;
  // The external cases, one line each, on the operation their source names.
  for (const std::string gen : {"reported", "cases"}) {
    std::vector<const ResultRow*> gen_rows;
    for (const auto& r : rows) {
      if (r.generator == gen) gen_rows.push_back(&r);
    }
    if (gen_rows.empty()) continue;
    const std::vector<ExternalCase>* corpus = nullptr;
    try {
      corpus = gen == "reported" ? &reported_corpus() : &user_cases();
    } catch (const std::exception&) {
    }
    const auto described = [&](const std::string& id) -> const ExternalCase* {
      if (corpus == nullptr) return nullptr;
      for (const auto& c : *corpus) {
        if (c.id == id) return &c;
      }
      return nullptr;
    };
    std::vector<std::string> ids;
    std::map<std::string, std::map<std::string, const ResultRow*>> on_named_op;  // id -> back end -> row
    for (const ResultRow* r : gen_rows) {
      if (std::find(ids.begin(), ids.end(), r->variant) == ids.end()) ids.push_back(r->variant);
      const ExternalCase* c = described(r->variant);
      if (r->regular && (c == nullptr || c->op == r->op)) on_named_op[r->variant][r->kernel] = r;
    }
    if (gen == "reported") {
      md << "## The reported corpus: public failure reports, today\n\n"
         << ids.size() << " cases from public issue reports (`experiments/reported/*.jsonl`), each with the input "
         << "as given in the report. For each: the operation the report names (regular), what the report says went "
            "wrong, and what every back end gives today. mkbool *refused* means the input lies outside mkbool's "
            "domain (e.g. a ring whose edges cross): mkbool says so rather than guess. Every operation of every case "
            "is in the tables above under generator `reported`.\n\n";
      // Per library the reports are about: how many of its reported cases it still fails. On a
      // case outside mkbool's domain there is no exact result: the counterpart is judged by
      // validity alone there (invalid output, crash, timeout), and an exception, which is how
      // GEOS refuses such input, is not counted as a failure.
      struct Tally {
        std::size_t cases = 0, outside = 0, failing = 0;
      };
      std::map<std::string, Tally> still;
      std::map<std::string, std::string> library_peer{{"GEOS", "geos"},       {"JTS", "geos"},
                                                      {"JSTS", "geos"},       {"shapely", "geos"},
                                                      {"Boost.Geometry", "boost"}, {"Clipper", "clipper"},
                                                      {"Clipper2", "clipper"}, {"CGAL", "cgal_epeck"}};
      for (const auto& id : ids) {
        const ExternalCase* c = described(id);
        if (c == nullptr) continue;
        auto& s = still[c->library];
        ++s.cases;
        const auto& runs = on_named_op[id];
        const auto refused = [](const auto& kernel_row) { return outcome(*kernel_row.second) == Outcome::refused; };
        const bool outside = std::any_of(runs.begin(), runs.end(), refused);
        if (outside) ++s.outside;
        const auto lp = library_peer.find(c->library);
        if (lp == library_peer.end()) continue;
        const auto it = runs.find(lp->second);
        if (it == runs.end()) continue;
        const Outcome o = outcome(*it->second);
        if (outside ? (o == Outcome::invalid_output || o == Outcome::crash || o == Outcome::timeout) : is_failure(o)) {
          ++s.failing;
        }
      }
      md << "| library reported on | cases | of them outside mkbool's domain | its counterpart here fails today "
            "|\n|---|---:|---:|---:|\n";
      for (const auto& [lib, s] : still) {
        const auto lp = library_peer.find(lib);
        md << "| " << lib << " | " << s.cases << " | " << s.outside << " | "
           << (lp == library_peer.end() ? std::string("(not a back end here)")
                                        : "`" + lp->second + "`: " + rate_with_interval(s.failing, s.cases))
           << " |\n";
      }
      md << "\nOn inputs outside mkbool's domain a counterpart fails only by invalid output, a crash or a "
            "timeout; an exception there (GEOS: the input is invalid) is not a failure. "
            "GEOS stands in for JTS, JSTS and shapely (same algorithms; shapely calls GEOS, JSTS ports JTS), "
            "Clipper 6.4 for Clipper2 (its predecessor: the same integer approach, not the same code).\n\n";
    } else {
      md << "## Your cases (`run --cases`)\n\n";
    }
    std::vector<std::string> cols2{"source", "library", "reported", "op"};
    cols2.insert(cols2.end(), backends.begin(), backends.end());
    md << "| case |";
    for (const auto& c : cols2) md << " " << c << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < cols2.size(); ++i) md << "---|";
    md << "\n";
    for (const auto& id : ids) {
      const ExternalCase* c = described(id);
      std::string op;
      for (const ResultRow* r : gen_rows) {
        if (r->variant == id && r->regular && (c == nullptr || c->op == r->op)) op = r->op;
      }
      md << "| " << id << " | " << (c ? c->source : "") << " | " << (c ? c->library : "") << " | "
         << markdown_cell(c ? c->reported : "") << " | " << op << " |";
      for (const auto& b : backends) {
        const auto it = on_named_op[id].find(b);
        md << " " << (it == on_named_op[id].end() ? std::string() : short_outcome(outcome(*it->second))) << " |";
      }
      md << "\n";
    }
    md << "\n";
  }
  return md.str();
}

}  // namespace mk::experiments
