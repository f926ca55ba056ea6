// The pieces of the _mkbool extension shared by its files: the input polygon handle, the
// result object, the exception types and the conversions between numpy and rings.
// [MK89 §2.2] (polygon model) [MK89 §3.2] (procedure polygonoperation)
// Preconditions: every function here runs with the GIL held unless it says otherwise.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

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
// the calls and the results that used it: converted once, never copied again.
struct InputPolygon {
  std::shared_ptr<const Polygon> polygon;
};

// One operation's request: what mk::compute gets, less the inputs.
struct Request {
  Operation op = Operation::intersection;
  BooleanOptions options;
};

// The options of a call, in the library's terms. Names and values as the command's flags;
// throws std::invalid_argument with the command's message for an unknown kernel or type.
BooleanOptions make_options(Operation op, const std::string& kernel, bool regular, bool area_exact, bool exact);
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

// A ring as a new float64 (n, 2) array, closed (first vertex repeated) when asked.
py::array_t<double> ring_array(const std::vector<Point>& ring, bool closed = false);

// The result object: the library's output and statistics, the inputs and request that gave
// them (for what is computed only when asked: exact area, exact coordinates), and the
// arrays built so far.
class Result {
 public:
  Result(std::shared_ptr<const Polygon> a, std::shared_ptr<const Polygon> b, Request request, BooleanOutput out);

  const Output& output() const { return out_.output; }
  const BooleanStats& stats() const { return out_.stats; }
  const Request& request() const { return request_; }
  const std::shared_ptr<const Polygon>& a() const { return a_; }
  const std::shared_ptr<const Polygon>& b() const { return b_; }

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

  std::shared_ptr<const Polygon> a_, b_;
  Request request_;
  BooleanOutput out_;
  std::optional<std::vector<std::vector<std::string>>> exact_;
  std::optional<bool> rounded_valid_;
  py::object polygons_, rings_;
};

// Runs one operation with the GIL released.
BooleanOutput run_compute(const Polygon& a, const Polygon& b, const BooleanOptions& options);

void bind_convert(py::module_& m);
void bind_result(py::module_& m);
void bind_batch(py::module_& m);
void bind_harness(py::module_& m);

}  // namespace mk::python
