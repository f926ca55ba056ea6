// The runs of pair and set cases through the library, and their exact references.
// [MK89 §3.2] [BRIEF §1, extended by issue 13]
// Preconditions: see operations.hpp.
#include "experiments/operations.hpp"

#include <stdexcept>

#include "experiments/artefacts.hpp"
#include "experiments/generators.hpp"

namespace mk::experiments {

namespace {

bool is_set_case(const CaseSpec& spec) { return is_set_generator(spec.generator); }

}  // namespace

bool runs_operation(const CaseSpec& spec, Operation op) {
  return !is_set_case(spec) || op == Operation::union_ || op == Operation::intersection;
}

std::string run_operation_name(const CaseSpec& spec, Operation op) {
  if (!is_set_case(spec)) return std::string(operation_name(op));
  return op == Operation::union_ ? "union_all" : op == Operation::intersection ? "intersection_all" : "none";
}

Operation parse_run_operation(const std::string& name) {
  if (name == "union_all") return Operation::union_;
  if (name == "intersection_all") return Operation::intersection;
  return parse_operation(name);
}

BooleanOutput run_operation(const Case& c, BooleanOptions options) {
  options.fill_rule = fill_rule_of(c.spec);
  if (!c.parts) return compute(c.a, c.b, options);
  if (!runs_operation(c.spec, options.op)) {
    throw std::invalid_argument(std::string("set cases run union and intersection only, not ") +
                                std::string(operation_name(options.op)));
  }
  return options.op == Operation::union_ ? union_all(*c.parts, options) : intersection_all(*c.parts, options);
}

ExactResult case_reference(const Case& c, Operation op, bool regular, bool paper_variants) {
  if (!c.parts) return exact_reference(c.a, c.b, op, regular, paper_variants, fill_rule_of(c.spec));
  BooleanOptions o{op, regular, "rational"};
  o.all_pairs = paper_variants;
  o.area = false;
  o.exact_coordinates = true;
  return exact_result_of(run_operation(c, o).output);
}

}  // namespace mk::experiments
