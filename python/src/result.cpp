// The result object: the library's Output in every form a Python user wants (WKT, WKB,
// GeoJSON, native JSON, SVG, numpy rings), the statistics of --stats, and what costs more
// than the operation (exact area, exact coordinates) computed only when asked.
// [MK89 §3.1 step 6] (irreducible result polygons and their types) [MK89 §2.2] (forest)
// Preconditions: the GIL is held except inside run_compute.
#include <gmpxx.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/boolean_op.hpp"  // before to_output.hpp: step6_construct.hpp needs EfEntry declared
#include "core/to_output.hpp"
#include "io/geojson.hpp"
#include "io/native_json.hpp"
#include "io/ring_rules.hpp"
#include "io/svg.hpp"
#include "io/wkb.hpp"
#include "io/wkt.hpp"
#include "module.hpp"

namespace mk::python {

namespace {

// WKT, WKB and GeoJSON describe finite areas; the command refuses the same case with exit 1.
void require_bounded(const Result& r, const char* format) {
  if (!r.output().unbounded) return;
  const Request& q = r.request();
  throw OutputError(std::string("the result of ") + q.name + " of A (" +
                    type_name(r.a()->type) + ") and B (" + type_name(r.b()->type) +
                    ") is unbounded (hole type), which " + format +
                    " cannot express; use .rings and .types, or .json (native JSON)");
}

// A ring as a closed float64 array turning the way asked, decided exactly (io/ring_rules).
py::array_t<double> oriented_ring(const Ring& ring, bool counterclockwise) {
  const int orientation = io_detail::ring_orientation(ring);
  if (orientation == 0 || (orientation > 0) == counterclockwise) return ring_array(ring, true);
  Ring reversed(ring.rbegin(), ring.rend());
  return ring_array(reversed, true);
}

// A rational "p/q" or "p" as two Python ints, read through hexadecimal: Python refuses to
// read decimal integers of more than 4300 digits (sys.get_int_max_str_digits), which exact
// areas and coordinates reach; powers of two as bases have no limit.
py::int_ python_int(const mpz_class& z) {
  const std::string hex = z.get_str(16);
  PyObject* v = PyLong_FromString(hex.c_str(), nullptr, 16);
  if (v == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::int_>(v);
}

py::tuple ratio(const std::string& text) {
  mpq_class q;
  if (q.set_str(text, 10) != 0) throw std::runtime_error("not a rational: " + text);
  q.canonicalize();
  return py::make_tuple(python_int(q.get_num()), python_int(q.get_den()));
}

// How the written coordinates were obtained, as the command's --stats "rounding" object
// (plus rounds and failure).
py::dict rounding_dict(const RoundingReport& r) {
  py::dict d;
  d["mode"] = r.mode == RoundingMode::certified ? "certified" : "nearest";
  d["snapped"] = r.snapped;
  d["grid"] = r.snapped ? py::object(py::str(r.grid)) : py::object(py::none());
  d["user_grid"] = r.user_grid;
  d["regridded"] = r.regridded;
  d["max_displacement"] = r.max_displacement ? py::object(py::float_(*r.max_displacement)) : py::object(py::none());
  d["hot_pixels"] = r.hot_pixels;
  d["incidences"] = r.incidences;
  d["rounds"] = r.rounds;
  d["valid"] = r.valid;
  d["failure"] = r.failure.empty() ? py::object(py::none()) : py::object(py::str(r.failure));
  return d;
}

py::dict stats_dict(Result& r) {
  const BooleanStats& s = r.stats();
  py::dict d;
  d["kernel"] = s.kernel;
  d["op_ns"] = s.op_ns;
  d["vertices_in"] = s.vertices_in;
  d["crossings"] = s.crossings;
  d["vertices_out"] = s.vertices_out;
  d["rounded_valid"] = r.rounded_valid();
  d["area"] = s.area ? py::object(py::float_(*s.area)) : py::object(py::none());
  d["area_beyond_double"] = s.area_beyond_double;
  d["area_exact"] = s.area_exact ? py::object(py::str(*s.area_exact)) : py::object(py::none());
  d["rounding"] = rounding_dict(r.output().rounding);
  return d;
}

}  // namespace

Result::Result(InputPolygon a, InputPolygon b, Request request, BooleanOutput out)
    : Result(a, b, std::move(request), std::move(out), [a, b](const BooleanOptions& o) { return compute_inputs(a, b, o); }) {}

Result::Result(InputPolygon a, InputPolygon b, Request request, BooleanOutput out, Rerun rerun)
    : a_(std::move(a)), b_(std::move(b)), request_(std::move(request)), out_(std::move(out)), rerun_(std::move(rerun)) {
  if (request_.options.exact_coordinates) {
    exact_.emplace();
    for (const auto& c : out_.output.irreducible) exact_->push_back(c.exact);
  }
}

BooleanOutput Result::recompute(bool area_exact, bool exact_coordinates) const {
  BooleanOptions o = request_.options;
  o.area = false;
  o.area_exact = area_exact;
  o.exact_coordinates = exact_coordinates;
  py::gil_scoped_release release;
  return rerun_(o);
}

InputPolygon input_from_result(Result& r) {
  const Output& o = r.output();
  if (is_exact_kernel(r.stats().kernel) && o.dangling_edges.empty() && o.isolated_points.empty()) {
    // The exact region: every cycle of 3+ vertices, nesting by parity (mk::exact_result).
    const auto& exact = r.exact_coordinates();
    ExactPolygon p;
    p.type = o.unbounded ? PolygonType::hole : PolygonType::island;
    for (std::size_t i = 0; i < o.irreducible.size(); ++i) {
      if (o.irreducible[i].vertices.size() < 3) continue;
      auto& ring = p.rings.emplace_back();
      for (std::size_t k = 0; k + 1 < exact[i].size(); k += 2) {
        RationalPoint q;
        if (q.x.set_str(exact[i][k], 10) != 0 || q.y.set_str(exact[i][k + 1], 10) != 0) {
          throw std::runtime_error("not a rational: " + exact[i][k] + ", " + exact[i][k + 1]);
        }
        q.x.canonicalize();
        q.y.canonicalize();
        ring.push_back(std::move(q));
      }
    }
    return input_from_exact(std::move(p));
  }
  // Inexact kernels and non-regular results: the rounded result. Bounded: its OGC polygons;
  // unbounded: every area cycle with the hole type (its region is the closure of the outside
  // of those cycles' finite area region).
  if (!o.unbounded) return InputPolygon(std::make_shared<const Polygon>(to_polygon(o.polygons)));
  Polygon p;
  p.type = PolygonType::hole;
  for (const auto& c : o.irreducible) {
    if (c.vertices.size() >= 3) p.rings.push_back(c.vertices);
  }
  return InputPolygon(std::make_shared<const Polygon>(std::move(p)));
}

const std::string& Result::area_exact() {
  if (out_.stats.area_exact) return *out_.stats.area_exact;
  if (!is_exact_kernel(out_.stats.kernel)) {
    throw std::invalid_argument("area_exact is given by the exact kernels only; this result is from kernel '" +
                                out_.stats.kernel + "' (use .area)");
  }
  if (out_.output.unbounded) throw OutputError("the result is unbounded (hole type): its area is infinite");
  out_.stats.area_exact = recompute(true, false).stats.area_exact;
  return *out_.stats.area_exact;
}

const std::vector<std::vector<std::string>>& Result::exact_coordinates() {
  if (exact_) return *exact_;
  if (!is_exact_kernel(out_.stats.kernel)) {
    throw std::invalid_argument("exact coordinates are given by the exact kernels only; this result is from kernel '" +
                                out_.stats.kernel + "' (use .rings)");
  }
  const BooleanOutput again = recompute(false, true);
  exact_.emplace();
  for (const auto& c : again.output.irreducible) exact_->push_back(c.exact);
  return *exact_;
}

bool Result::rounded_valid() {
  if (out_.output.rounded_valid) return *out_.output.rounded_valid;
  if (!rounded_valid_) {
    // Inexact kernels: checked here as the command's --stats does (cli/stats.cpp).
    std::vector<std::vector<Point>> rings;
    rings.reserve(out_.output.irreducible.size());
    for (const auto& c : out_.output.irreducible) rings.push_back(c.vertices);
    py::gil_scoped_release release;
    rounded_valid_ = is_valid_rounded_output<ExactKernel>(rings);
  }
  return *rounded_valid_;
}

py::list Result::polygons() {
  if (!polygons_) {
    py::list out;
    for (const OgcPolygon& p : out_.output.polygons) {
      py::list rings;
      rings.append(oriented_ring(p.shell, true));
      for (const Ring& h : p.holes) rings.append(oriented_ring(h, false));
      out.append(rings);
    }
    polygons_ = out;
  }
  return polygons_;
}

py::list Result::rings() {
  if (!rings_) {
    py::list out;
    for (const auto& c : out_.output.irreducible) out.append(ring_array(c.vertices));
    rings_ = out;
  }
  return rings_;
}

void bind_result(py::module_& m) {
  py::class_<Result>(m, "Result", "The result of one Boolean operation.")
      .def_property_readonly("op", [](const Result& r) { return r.request().name; })
      .def_property_readonly("kernel", [](const Result& r) { return r.stats().kernel; })
      .def_property_readonly("regular", [](const Result& r) { return r.request().options.regular; })
      .def_property_readonly("unbounded", [](const Result& r) { return r.output().unbounded; })
      .def_property_readonly("wkt", [](const Result& r) {
        require_bounded(r, "WKT");
        return write_wkt(r.output());
      })
      .def_property_readonly("wkb", [](const Result& r) {
        require_bounded(r, "WKB");
        return py::bytes(write_wkb(r.output()));
      })
      .def_property_readonly("geojson", [](const Result& r) {
        require_bounded(r, "GeoJSON");
        return write_geojson(r.output());
      })
      .def_property_readonly("json", [](Result& r) {
        if (r.request().options.exact_coordinates || !is_exact_kernel(r.stats().kernel)) {
          return write_native_json(r.output(), r.stats().kernel);
        }
        // The native format carries exact coordinates for exact kernels.
        Output o = r.output();
        const auto& exact = r.exact_coordinates();
        for (std::size_t i = 0; i < o.irreducible.size(); ++i) o.irreducible[i].exact = exact[i];
        return write_native_json(o, r.stats().kernel);
      })
      .def_property_readonly("svg", [](const Result& r) { return write_svg(*r.a(), *r.b(), r.output()); })
      .def_property_readonly("area", [](const Result& r) {
        if (r.output().unbounded) return std::numeric_limits<double>::infinity();
        return r.stats().area.value_or(0.0);
      })
      .def_property_readonly("_area_exact_text", &Result::area_exact)
      .def_property_readonly("_exact_text", &Result::exact_coordinates)
      // As (numerator, denominator) ints: what mkbool.Result turns into Fractions.
      .def_property_readonly("_area_exact_ratio", [](Result& r) { return ratio(r.area_exact()); })
      .def_property_readonly("_exact_ratios", [](Result& r) {
        py::list out;
        for (const auto& cycle : r.exact_coordinates()) {
          py::list c;
          for (const auto& v : cycle) c.append(ratio(v));
          out.append(c);
        }
        return out;
      })
      .def_property_readonly("rounded_valid", &Result::rounded_valid)
      .def_property_readonly("polygons", &Result::polygons)
      .def_property_readonly("rings", &Result::rings)
      .def_property_readonly("types", [](const Result& r) {
        py::list t;
        for (const auto& c : r.output().irreducible) t.append(type_name(c.type));
        return t;
      })
      .def_property_readonly("dangling_edges", [](const Result& r) {
        const auto& e = r.output().dangling_edges;
        py::array_t<double> a({static_cast<py::ssize_t>(e.size()), py::ssize_t{2}, py::ssize_t{2}});
        double* out = a.mutable_data();
        for (std::size_t i = 0; i < e.size(); ++i) {
          out[4 * i] = e[i].first.x;
          out[4 * i + 1] = e[i].first.y;
          out[4 * i + 2] = e[i].second.x;
          out[4 * i + 3] = e[i].second.y;
        }
        return a;
      })
      .def_property_readonly("isolated_points", [](const Result& r) { return ring_array(r.output().isolated_points); })
      .def_property_readonly("stats", &stats_dict)
      .def_property_readonly("rounding", [](const Result& r) { return rounding_dict(r.output().rounding); })
      .def_property_readonly("fill_rule", [](const Result& r) {
        const auto& rule = r.request().options.fill_rule;
        return rule ? py::object(py::str(std::string(fill_rule_name(*rule)))) : py::object(py::none());
      })
      .def_property_readonly("grid", [](const Result& r) {
        const std::string& g = r.request().options.grid;
        return g.empty() ? py::object(py::none()) : py::object(py::str(g));
      })
      .def("exact_polygon", &input_from_result,
           "The result as an input polygon, exactly (exact kernels, regular results); see input_from_result.")
      .def_property_readonly("inputs", [](const Result& r) { return py::make_tuple(r.input_a(), r.input_b()); })
      .def_property_readonly("is_empty", [](const Result& r) {
        const Output& o = r.output();
        return !o.unbounded && o.irreducible.empty();
      });
}

}  // namespace mk::python
