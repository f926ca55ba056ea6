// What one run of a case computes, for pair cases and set cases alike: A op B through
// mk::compute, or for a set case (Case::parts) the N-ary operation the binary one stands
// for, union -> mk::union_all and intersection -> mk::intersection_all (difference and xor
// have no N-ary counterpart and do not run); each with the case's fill rule, if any.
// [MK89 §3.2] [BRIEF §1, extended by issue 13] (N-ary operations, fill rules)
// Preconditions: cases come from make_case (or carry their own inputs, as external ones).
#pragma once

#include <string>

#include "api/mkbool.hpp"
#include "experiments/case.hpp"
#include "experiments/verdict.hpp"

namespace mk::experiments {

// Whether a case's runs include `op`: every operation for pair cases, union and
// intersection for set cases.
bool runs_operation(const CaseSpec& spec, Operation op);

// The CSV's op column: operation_name(op), or union_all / intersection_all for a set case.
std::string run_operation_name(const CaseSpec& spec, Operation op);

// The operation of an op column or a command line (intersection, union, difference, xor,
// union_all, intersection_all); throws std::invalid_argument.
Operation parse_run_operation(const std::string& name);

// One kernel's run of the case: options.op, regular and kernel as given, the fill rule the
// case's (fill_rule_of). Throws what the library throws.
BooleanOutput run_operation(const Case& c, BooleanOptions options);

// The exact reference of that run: exact_reference for pair cases, the N-ary operation with
// RationalKernel through the library for set cases (all-pairs search with paper_variants).
ExactResult case_reference(const Case& c, Operation op, bool regular, bool paper_variants);

}  // namespace mk::experiments
