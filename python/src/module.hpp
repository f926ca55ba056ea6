// The pieces of the _mkbool extension shared by its files: the input polygon handle, the
// result object, the exception types and the conversions between numpy and rings.
// [MK89 §2.2] (polygon model) [MK89 §3.2] (procedure polygonoperation)
// Preconditions: every function here runs with the GIL held unless it says otherwise.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/mkbool.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk::python {

namespace py = pybind11;

// A result that exists but cannot be given in the form asked for (an unbounded result as
// WKT, WKB or GeoJSON): mkbool.OutputError, as the command's exit code 1 for the same case.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An input polygon as the library takes it (rings plus island/hole type), shared between
// the calls and the results that used it: converted once, never copied again. `exact` holds
// the polygon exactly when some coordinate is not a double (Fractions, an exact result fed
// back in); `polygon` then holds the nearest doubles, for pictures and messages only.
struct InputPolygon {
  std::shared_ptr<const Polygon> polygon;
  std::shared_ptr<const ExactPolygon> exact;

  InputPolygon() = default;
  explicit InputPolygon(std::shared_ptr<const Polygon> p, std::shared_ptr<const ExactPolygon> e = nullptr)
      : polygon(std::move(p)), exact(std::move(e)) {}
};

// The polygon exactly: doubles only when every coordinate is one (then `exact` is empty).
// Throws mk::InvalidInput for a coordinate beyond the range of doubles.
InputPolygon input_from_exact(ExactPolygon p);

// The parts of an OGC input read without checking them against each other or themselves
// (io/format.hpp, read_parts_input): what fill rules and the N-ary operations read.
struct InputParts {
  std::shared_ptr<const MultiPolygon> parts;
};

// One operation's request: what mk::compute gets, less the inputs; `name` is the
// operation's name in results ("union", "union_all", "make_valid", ...).
struct Request {
  Operation op = Operation::intersection;
  std::string name;
  BooleanOptions options;
};

// The options of a call in the library's terms, names and values as the command's flags
// (fill rule: evenodd, nonzero, positive, negative, union or empty; rounding: certified or
// nearest; grid: exact decimal or p/q text, empty for none). Throws std::invalid_argument
// with the command's message for an unknown kernel, fill rule, rounding or a bad grid.
BooleanOptions make_options(Operation op, const std::string& kernel, bool regular, bool area_exact, bool exact,
                            const std::string& fill_rule = {}, const std::string& grid = {},
                            const std::string& rounding = "certified");
std::optional<FillRule> fill_rule_named(const std::string& name);
Operation operation_named(const std::string& name);
// The command's message for a kernel failure, naming the exact kernel that never fails.
std::string kernel_failure_message(const KernelFailure& e);
PolygonType type_named(const std::string& name);
std::string type_name(PolygonType t);

// The rings of a polygon as float64 (n, 2) arrays: closing vertex dropped, repeated
// consecutive vertices removed, non-finite coordinates refused naming ring and vertex
// (mk::InvalidInput "ring R, vertex V: ..."). Arrays are read in place (no intermediate
// copy) when they are C-contiguous float64 already.
Polygon polygon_from_arrays(const py::sequence& rings, PolygonType type);

// The bytes of a WKB buffer; mk::InvalidInput unless contiguous bytes.
std::string buffer_bytes(const py::buffer& b);

// A ring as a new float64 (n, 2) array, closed (first vertex repeated) when asked.
py::array_t<double> ring_array(const std::vector<Point>& ring, bool closed = false);

// Runs the operation that gave a result again with other options (exact area, exact
// coordinates asked for later); called with the GIL released.
using Rerun = std::function<BooleanOutput(const BooleanOptions&)>;

// One binary operation on two inputs, exact ones over rationals (mk::compute over
// ExactPolygon). Fill rules read doubles only: an exact input that is not doubles is refused
// (std::invalid_argument) rather than read without its rule. Runs with the GIL as it finds it.
BooleanOutput compute_inputs(const InputPolygon& a, const InputPolygon& b, const BooleanOptions& options);

// The result object: the library's output and statistics, the inputs and request that gave
// them (for what is computed only when asked: exact area, exact coordinates), and the
// arrays built so far. For the N-ary operations `a` is the input's rings as drawn and `b`
// is empty.
class Result {
 public:
  // A binary operation's result (rerun: compute_inputs on a and b).
  Result(InputPolygon a, InputPolygon b, Request request, BooleanOutput out);
  Result(InputPolygon a, InputPolygon b, Request request, BooleanOutput out, Rerun rerun);

  const Output& output() const { return out_.output; }
  const BooleanStats& stats() const { return out_.stats; }
  const Request& request() const { return request_; }
  const std::shared_ptr<const Polygon>& a() const { return a_.polygon; }
  const std::shared_ptr<const Polygon>& b() const { return b_.polygon; }
  const InputPolygon& input_a() const { return a_; }
  const InputPolygon& input_b() const { return b_; }

  // The exact area as "p/q" (exact kernels), computing it now if the call did not ask.
  const std::string& area_exact();
  // Exact coordinates of the irreducible polygons, "p/q" per coordinate (exact kernels).
  const std::vector<std::vector<std::string>>& exact_coordinates();
  // Whether the rounded output is valid, checked exactly (as --stats reports it).
  bool rounded_valid();

  py::list polygons();  // cached
  py::list rings();     // cached

 private:
  BooleanOutput recompute(bool area_exact, bool exact_coordinates) const;

  InputPolygon a_, b_;
  Request request_;
  BooleanOutput out_;
  Rerun rerun_;
  std::optional<std::vector<std::vector<std::string>>> exact_;
  std::optional<bool> rounded_valid_;
  py::object polygons_, rings_;
};

// Runs one operation with the GIL released.
BooleanOutput run_compute(const InputPolygon& a, const InputPolygon& b, const BooleanOptions& options);

// A result as the next operation's input: exactly (its exact cycles, rationals where they
// are not doubles) for exact kernels' regular results; otherwise its rounded polygons, or
// its rounded cycles with the hole type when unbounded.
InputPolygon input_from_result(Result& r);

// The cache of large freed blocks kept for the next call (memory.cpp).
struct MemoryCacheState {
  std::size_t cached_bytes = 0;
  std::size_t blocks = 0;
  std::size_t limit_bytes = 0;
};
MemoryCacheState memory_cache_state();
void set_memory_cache_limit(std::size_t bytes);  // frees kept blocks beyond it
void release_memory_cache();                     // frees every kept block

void bind_convert(py::module_& m);
void bind_fill(py::module_& m);
void bind_result(py::module_& m);
void bind_batch(py::module_& m);
void bind_harness(py::module_& m);

}  // namespace mk::python
