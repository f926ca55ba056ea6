// Fill rules and the N-ary operations from Python: inputs read as parts without checking them
// (any rings: crossing, overlapping, repeated), a rule applied as the command applies it, and
// union_all, intersection_all and make_valid over one arrangement of all rings.
// [MK89 §3.1] paper-notes.md deviation 17 (winding numbers) [BRIEF §1] [OGC06-103 §6.1.11]
// Preconditions: the GIL is held except around the library's calls.
#include <gmpxx.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "arithmetic/nearest_double.hpp"
#include "io/format.hpp"
#include "io/ring_rules.hpp"
#include "io/wkb.hpp"
#include "module.hpp"

namespace mk::python {

namespace {

InputParts shared_parts(MultiPolygon mp) { return {std::make_shared<const MultiPolygon>(std::move(mp))}; }

// A ring turned the way asked, decided exactly; a ring of zero area is left as given.
Ring turned(const Ring& r, bool counterclockwise) {
  const int s = io_detail::ring_orientation(r);
  if (s == 0 || (s > 0) == counterclockwise) return r;
  return Ring(r.rbegin(), r.rend());
}

// Whether every exact coordinate of the result is a double (then its rounded cycles are it).
bool exact_coordinates_are_doubles(Result& r) {
  for (const auto& cycle : r.exact_coordinates()) {
    for (const auto& text : cycle) {
      mpq_class q;
      if (q.set_str(text, 10) != 0) return false;
      q.canonicalize();
      const double d = nearest_double(q);
      if (!std::isfinite(d) || cmp(mpq_class(d), q) != 0) return false;
    }
  }
  return true;
}

// A result as parts: its OGC polygons, shells counterclockwise and holes clockwise, when
// they are the result exactly (or the kernel is not exact: then they are all there is).
InputParts parts_of_result(Result& r) {
  const Output& o = r.output();
  if (o.unbounded) {
    throw InvalidInput("an unbounded result (hole type) has no shells and holes for a fill rule or the N-ary "
                       "operations; intersect it with a bounded polygon first");
  }
  if (is_exact_kernel(r.stats().kernel) && (o.rounding.snapped || !exact_coordinates_are_doubles(r))) {
    throw std::invalid_argument(
        "fill rules and the N-ary operations read coordinates that are doubles, and this result's exact polygons "
        "are not doubles (or were snapped onto a grid): give its rounded form (the result's .wkb) to read those, "
        "or use it without a fill rule (exactly)");
  }
  MultiPolygon mp;
  mp.reserve(o.polygons.size());
  for (const OgcPolygon& p : o.polygons) {
    OgcPolygon& q = mp.emplace_back();
    q.shell = turned(p.shell, true);
    for (const Ring& h : p.holes) q.holes.push_back(turned(h, false));
  }
  return shared_parts(std::move(mp));
}

// Rings as one part: the first the shell, the others its holes (GeoJSON's order).
InputParts parts_of_arrays(const py::sequence& rings) {
  Polygon p = polygon_from_arrays(rings, PolygonType::island);
  MultiPolygon mp;
  if (!p.rings.empty()) {
    OgcPolygon& part = mp.emplace_back();
    part.shell = std::move(p.rings.front());
    for (std::size_t i = 1; i < p.rings.size(); ++i) part.holes.push_back(std::move(p.rings[i]));
  }
  return shared_parts(std::move(mp));
}

using PartsOperation = BooleanOutput (*)(const MultiPolygon&, const BooleanOptions&);

PartsOperation parts_operation(const std::string& name) {
  if (name == "union_all") return &union_all;
  if (name == "intersection_all") return &intersection_all;
  if (name == "make_valid") return &make_valid;
  throw std::invalid_argument("unknown operation '" + name + "' (union_all, intersection_all or make_valid)");
}

}  // namespace

void bind_fill(py::module_& m) {
  py::class_<InputParts>(m, "InputParts",
                         "The parts (shells with their holes) of an input, read without checking them: what fill "
                         "rules and the N-ary operations read.")
      .def_property_readonly("part_count", [](const InputParts& p) { return p.parts->size(); })
      .def_property_readonly("ring_count", [](const InputParts& p) {
        std::size_t n = 0;
        for (const OgcPolygon& part : *p.parts) n += 1 + part.holes.size();
        return n;
      })
      .def("__repr__", [](const InputParts& p) {
        return "<mkbool.InputParts: " + std::to_string(p.parts->size()) + " parts>";
      });

  // WKT (also one geometry per line) or GeoJSON; native JSON has no parts and is refused.
  m.def("parts_from_text", [](const std::string& text) { return shared_parts(read_parts_input(text, "")); },
        py::arg("text"));
  m.def("parts_from_wkb", [](const py::buffer& bytes) { return shared_parts(read_wkb(buffer_bytes(bytes))); },
        py::arg("wkb"));
  m.def("parts_from_arrays", &parts_of_arrays, py::arg("rings"));
  m.def("parts_from_result", &parts_of_result, py::arg("result"));
  // The rings of the parts as the rule reads them (for "union": shells counterclockwise,
  // holes clockwise), as one polygon of the given type.
  m.def("by_rule", [](const InputParts& parts, const std::string& rule, const std::string& type) {
    const std::optional<FillRule> r = fill_rule_named(rule);
    if (!r) throw std::invalid_argument("by_rule needs a fill rule");
    Polygon p = fill_rule_polygon(*parts.parts, *r);
    p.type = type_named(type);
    return InputPolygon(std::make_shared<const Polygon>(std::move(p)));
  }, py::arg("parts"), py::arg("rule"), py::arg("type") = "island");

  // elements: the inputs are the polygons (a Python iterable), not the parts of one input.
  m.def(
      "compute_all",
      [](const std::string& name, const std::vector<InputParts>& inputs, const std::string& kernel,
         const std::string& fill_rule, const std::string& grid, const std::string& rounding, bool area_exact,
         bool exact, bool elements) {
        PartsOperation run = parts_operation(name);
        Request request{Operation::union_, name, {}};
        request.options = make_options(Operation::union_, kernel, true, area_exact, exact, fill_rule, grid, rounding);
        auto all = std::make_shared<MultiPolygon>();
        bool empty_element = false;
        for (const InputParts& in : inputs) {
          all->insert(all->end(), in.parts->begin(), in.parts->end());
          empty_element = empty_element || in.parts->empty();
        }
        if (elements && empty_element && run == &intersection_all) {
          // One of the polygons given is empty: so is the intersection (the union of nothing).
          all->clear();
          run = &union_all;
        }
        std::shared_ptr<const MultiPolygon> parts = std::move(all);
        BooleanOutput out;
        {
          py::gil_scoped_release release;
          out = run(*parts, request.options);
        }
        // The input as the command's pictures draw it: every ring as the rule reads it.
        const FillRule drawn_rule =
            request.options.fill_rule.value_or(name == "make_valid" ? FillRule::evenodd : FillRule::union_);
        InputPolygon drawn(std::make_shared<const Polygon>(fill_rule_polygon(*parts, drawn_rule)));
        InputPolygon nothing(std::make_shared<const Polygon>());
        return Result(std::move(drawn), std::move(nothing), std::move(request), std::move(out),
                      [parts, run](const BooleanOptions& o) { return run(*parts, o); });
      },
      py::arg("name"), py::arg("inputs"), py::arg("kernel") = "", py::arg("fill_rule") = "", py::arg("grid") = "",
      py::arg("rounding") = "certified", py::arg("area_exact") = false, py::arg("exact") = false,
      py::arg("elements") = false);
}

}  // namespace mk::python
