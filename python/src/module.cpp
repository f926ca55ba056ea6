// The _mkbool extension: exceptions with the command's messages, kernels, one operation,
// and the registration of the other parts (convert, result, batch, harness).
// [MK89 §3.2] (procedure polygonoperation: inputs, types, operation, regularity)
// Preconditions: loaded by the mkbool package (python/mkbool/__init__.py), which turns
// every accepted input into an InputPolygon before calling here.
#include <mpfr.h>

#include <chrono>
#include <cstdint>
#include <new>
#include <stdexcept>

#include "arithmetic/snap_grid.hpp"
#include "module.hpp"

namespace mk::python {

namespace {

// The exception types, created once with the module and alive as long as the process.
struct ExceptionTypes {
  py::handle error, invalid_input, kernel_failure, output_error, usage_error;
};
ExceptionTypes exception_types;

py::handle new_exception(py::module_& m, const char* name, py::tuple bases, const char* doc) {
  const std::string qualified = std::string("mkbool.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.attr(name) = py::handle(type);
  return type;  // the module's attribute keeps a reference; this one is never released
}

void register_exceptions(py::module_& m) {
  const py::handle value_error(PyExc_ValueError), runtime_error(PyExc_RuntimeError);
  auto& t = exception_types;
  t.error = new_exception(m, "Error", py::make_tuple(py::handle(PyExc_Exception)), "Base of every mkbool error.");
  t.invalid_input = new_exception(m, "InvalidInput", py::make_tuple(t.error, value_error),
                                  "Input that is malformed or outside the domain (the command's exit code 3); "
                                  "the message names what and where.");
  t.usage_error = new_exception(m, "UsageError", py::make_tuple(t.error, value_error),
                                "A call that asks for something that does not exist (unknown kernel, operation "
                                "or type: the command's exit code 2).");
  t.kernel_failure = new_exception(m, "KernelFailure", py::make_tuple(t.error, runtime_error),
                                   "An inexact kernel produced an inconsistent arrangement; exact kernels never do.");
  t.output_error = new_exception(m, "OutputError", py::make_tuple(t.error, value_error),
                                 "A result that cannot be given in the form asked for (an unbounded result as WKT, "
                                 "WKB or GeoJSON).");
  py::register_exception_translator([](std::exception_ptr p) {
    const auto& t = exception_types;
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      PyErr_SetString(t.invalid_input.ptr(), e.what());
    } catch (const KernelFailure& e) {
      PyErr_SetString(t.kernel_failure.ptr(), kernel_failure_message(e).c_str());
    } catch (const OutputError& e) {
      PyErr_SetString(t.output_error.ptr(), e.what());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(t.usage_error.ptr(), e.what());
    }
  });
}

InputPolygon with_type(const InputPolygon& p, const py::object& type) {
  if (type.is_none()) return p;
  const PolygonType t = type_named(type.cast<std::string>());
  if (t == p.polygon->type) return p;
  auto copy = std::make_shared<Polygon>(*p.polygon);
  copy->type = t;
  std::shared_ptr<ExactPolygon> exact;
  if (p.exact) {
    exact = std::make_shared<ExactPolygon>(*p.exact);
    exact->type = t;
  }
  return InputPolygon(std::move(copy), std::move(exact));
}

}  // namespace

Operation operation_named(const std::string& name) {
  if (name == "intersection") return Operation::intersection;
  if (name == "union") return Operation::union_;
  if (name == "difference") return Operation::difference;
  if (name == "xor" || name == "symmetric_difference") return Operation::symmetric_difference;
  throw std::invalid_argument("unknown operation '" + name +
                              "' (intersection, union, difference, symmetric_difference or xor)");
}

PolygonType type_named(const std::string& name) {
  if (name == "island") return PolygonType::island;
  if (name == "hole") return PolygonType::hole;
  throw std::invalid_argument("unknown polygon type '" + name + "' (island or hole)");
}

std::string kernel_failure_message(const KernelFailure& e) {
  return std::string("the kernel failed (inexact arithmetic): ") + e.what() + "; an exact kernel (kernel='" +
         std::string(default_kernel()) + "') never does";
}

std::string type_name(PolygonType t) { return t == PolygonType::island ? "island" : "hole"; }

std::optional<FillRule> fill_rule_named(const std::string& name) {
  if (name.empty()) return std::nullopt;
  for (const FillRule r : {FillRule::evenodd, FillRule::nonzero, FillRule::positive, FillRule::negative, FillRule::union_}) {
    if (name == fill_rule_name(r)) return r;
  }
  throw std::invalid_argument("unknown fill rule '" + name + "' (evenodd, nonzero, positive, negative or union)");
}

BooleanOptions make_options(Operation op, const std::string& kernel, bool regular, bool area_exact, bool exact,
                            const std::string& fill_rule, const std::string& grid, const std::string& rounding) {
  if (!kernel.empty()) {
    bool known = false;
    std::string names;
    for (const auto k : kernel_names()) {
      known = known || k == kernel;
      names += (names.empty() ? "" : ", ") + std::string(k);
    }
    if (!known) throw std::invalid_argument("unknown kernel '" + kernel + "' (built: " + names + ")");
  }
  BooleanOptions o;
  o.op = op;
  o.kernel = kernel;
  o.regular = regular;
  o.area = true;
  o.area_exact = area_exact;
  o.exact_coordinates = exact;
  o.fill_rule = fill_rule_named(fill_rule);
  if (rounding == "certified") {
    o.rounding = RoundingMode::certified;
  } else if (rounding == "nearest") {
    o.rounding = RoundingMode::nearest;
  } else {
    throw std::invalid_argument("unknown rounding '" + rounding + "' (certified or nearest)");
  }
  if (!grid.empty()) {
    if (o.rounding == RoundingMode::nearest) {
      throw std::invalid_argument("grid_size= snaps the result, which rounding='nearest' does not");
    }
    (void)SnapGrid::parse(grid);  // its message before any work (the N-ary operations parse it last)
    o.grid = grid;
  }
  return o;
}

BooleanOutput compute_inputs(const InputPolygon& a, const InputPolygon& b, const BooleanOptions& options) {
  if (!a.exact && !b.exact) return compute(*a.polygon, *b.polygon, options);
  if (options.fill_rule) {
    // mk::compute over ExactPolygon would run the paper's operation without the rule.
    throw std::invalid_argument(std::string("fill rules read coordinates that are doubles; ") + (a.exact ? "A" : "B") +
                                " has coordinates that are not (Fractions, or an exact result): give its rounded "
                                "form (a result's .wkb) to read it by a fill rule");
  }
  return compute(a.exact ? *a.exact : exact_polygon(*a.polygon), b.exact ? *b.exact : exact_polygon(*b.polygon), options);
}

BooleanOutput run_compute(const InputPolygon& a, const InputPolygon& b, const BooleanOptions& options) {
  py::gil_scoped_release release;
  return compute_inputs(a, b, options);
}

}  // namespace mk::python

PYBIND11_MODULE(_mkbool, m) {
  using namespace mk;
  using namespace mk::python;
  m.doc() = "mkbool's C++ core: exact Boolean operations on polygons (Margalit & Knott 1989).";
  register_exceptions(m);

  m.def("kernel_names", [] {
    py::list names;
    for (const auto k : mk::kernel_names()) names.append(py::str(std::string(k)));
    return names;
  }, "Names of the kernels built into this library, fastest exact one first.");
  m.def("default_kernel", [] { return std::string(mk::default_kernel()); });
  m.def("is_exact_kernel", [](const std::string& name) { return mk::is_exact_kernel(name); });
  // MPFR keeps its exponent range per thread only when built thread-safe; the batch runs
  // in one thread otherwise (batch.cpp).
  m.def("mpfr_is_thread_safe", [] { return mpfr_buildopt_tls_p() != 0; });

  m.def("memory_cache", [] {
    const MemoryCacheState s = memory_cache_state();
    py::dict d;
    d["cached_bytes"] = s.cached_bytes;
    d["blocks"] = s.blocks;
    d["limit_bytes"] = s.limit_bytes;
    return d;
  }, "The large blocks (256 KiB and more) freed by the library and kept for its next call.");
  m.def("set_memory_cache_limit", [](std::size_t bytes) { set_memory_cache_limit(bytes); }, py::arg("bytes"),
        "At most this many bytes of freed blocks are kept (0: none); kept blocks beyond it are freed.");
  m.def("release_memory", [] { release_memory_cache(); }, "Frees every kept block.");

  bind_convert(m);
  bind_result(m);
  bind_batch(m);
  bind_harness(m);
  bind_fill(m);

  m.def(
      "compute",
      [](const std::string& op, const InputPolygon& a, const InputPolygon& b, const std::string& kernel, bool regular,
         const py::object& a_type, const py::object& b_type, bool area_exact, bool exact, const std::string& fill_rule,
         const std::string& grid, const std::string& rounding) {
        Request request{operation_named(op), {}, {}};
        request.name = std::string(operation_name(request.op));
        request.options = make_options(request.op, kernel, regular, area_exact, exact, fill_rule, grid, rounding);
        const InputPolygon ta = with_type(a, a_type), tb = with_type(b, b_type);
        BooleanOutput out = run_compute(ta, tb, request.options);
        return Result(ta, tb, request, std::move(out));
      },
      py::arg("op"), py::arg("a"), py::arg("b"), py::arg("kernel") = "", py::arg("regular") = true,
      py::arg("a_type") = py::none(), py::arg("b_type") = py::none(), py::arg("area_exact") = false,
      py::arg("exact") = false, py::arg("fill_rule") = "", py::arg("grid") = "", py::arg("rounding") = "certified");
  m.def("with_type", &with_type, py::arg("polygon"), py::arg("type"));
  // For bench/python_speed.py: the C++ call alone (mk::compute on converted inputs, with
  // the module's default options), timed in C++ `repeats` times; nanoseconds per call.
  m.def(
      "_time_compute",
      [](const std::string& op, const InputPolygon& a, const InputPolygon& b, const std::string& kernel, int repeats) {
        const BooleanOptions o = make_options(operation_named(op), kernel, true, false, false);
        std::vector<std::int64_t> ns;
        py::gil_scoped_release release;
        for (int i = 0; i < repeats; ++i) {
          const auto t0 = std::chrono::steady_clock::now();
          const BooleanOutput out = compute(*a.polygon, *b.polygon, o);
          ns.push_back(std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count());
        }
        return ns;
      },
      py::arg("op"), py::arg("a"), py::arg("b"), py::arg("kernel") = "", py::arg("repeats") = 1);
}
