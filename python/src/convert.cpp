// Inputs into the library's polygon model: numpy rings, WKT, WKB (shapely's form), GeoJSON
// and native JSON text (multi-part OGC input checked as the command checks it, io/parts.hpp);
// and rings back out as numpy arrays.
// [MK89 §2.2] (rings plus type; one- and two-sided rings) [OGC06-103 §7, §8] [RFC7946]
// Preconditions: the GIL is held.
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/format.hpp"
#include "io/parts.hpp"
#include "io/wkb.hpp"
#include "io/wkt.hpp"
#include "module.hpp"

namespace mk::python {

namespace {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

InputPolygon shared(Polygon p) { return InputPolygon(std::make_shared<const Polygon>(std::move(p))); }

// Exact coordinates as mkbool's Python side writes them: "p/q" or "p" in hexadecimal (no
// limit on digits, unlike Python's decimal int-to-text conversion).
mpq_class hex_rational(const std::string& text, const std::string& where) {
  mpq_class q;
  if (text.empty() || q.set_str(text, 16) != 0 || q.get_den() == 0) throw InvalidInput(where + ": not a rational: " + text);
  q.canonicalize();
  return q;
}

// Rings of exact coordinates (per ring: x0, y0, x1, y1, ... as hex_rational text), with the
// closing vertex and repeated consecutive vertices dropped as polygon_from_arrays does.
ExactPolygon exact_from_texts(const std::vector<std::vector<std::string>>& rings, PolygonType type) {
  ExactPolygon p;
  p.type = type;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const std::string where = "ring " + std::to_string(r);
    const auto& t = rings[r];
    if (t.empty()) throw InvalidInput(where + ": ring is empty");
    if (t.size() % 2 != 0) throw InvalidInput(where + ": an odd number of coordinates");
    ExactRing ring;
    for (std::size_t v = 0; v < t.size(); v += 2) {
      const std::string at = where + ", vertex " + std::to_string(v / 2);
      RationalPoint q{hex_rational(t[v], at), hex_rational(t[v + 1], at)};
      if (ring.empty() || !(q.x == ring.back().x && q.y == ring.back().y)) ring.push_back(std::move(q));
    }
    while (ring.size() > 1 && ring.back().x == ring.front().x && ring.back().y == ring.front().y) ring.pop_back();
    p.rings.push_back(std::move(ring));
  }
  return p;
}

py::list ring_list(const Polygon& p) {
  py::list out;
  for (const Ring& r : p.rings) out.append(ring_array(r));
  return out;
}

}  // namespace

std::string buffer_bytes(const py::buffer& b) {
  const py::buffer_info info = b.request();
  if (info.itemsize != 1 || info.ndim != 1 || (info.strides.size() == 1 && info.strides[0] != 1)) {
    throw InvalidInput("WKB must be a contiguous byte string (bytes, bytearray or memoryview)");
  }
  return std::string(static_cast<const char*>(info.ptr), static_cast<std::size_t>(info.size));
}

InputPolygon input_from_exact(ExactPolygon p) {
  if (auto d = as_double_polygon(p)) return InputPolygon(std::make_shared<const Polygon>(std::move(*d)));
  validate_exact_coordinates(p, "");
  auto nearest = std::make_shared<const Polygon>(nearest_polygon(p));
  return InputPolygon(std::move(nearest), std::make_shared<const ExactPolygon>(std::move(p)));
}

Polygon polygon_from_arrays(const py::sequence& rings, PolygonType type) {
  Polygon p;
  p.type = type;
  p.rings.reserve(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const std::string where = "ring " + std::to_string(r);
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(rings[r]);
    if (!a) throw InvalidInput(where + ": not an array of numbers");
    if (a.ndim() != 2 || a.shape(1) != 2) {
      throw InvalidInput(where + ": expected vertices of shape (n, 2), got shape " + shape_text(a));
    }
    const auto n = static_cast<std::size_t>(a.shape(0));
    if (n == 0) throw InvalidInput(where + ": ring is empty");
    // One pass from the array into the ring, for finiteness and the paper's form as native
    // JSON takes it (no closing vertex, no zero-length edge); faster than pushing vertex
    // by vertex.
    Ring ring(n);
    const double* d = a.data();
    std::size_t kept = 0;
    for (std::size_t v = 0; v < n; ++v) {
      const Point q{d[2 * v], d[2 * v + 1]};
      if (!std::isfinite(q.x) || !std::isfinite(q.y)) {
        throw InvalidInput(where + ", vertex " + std::to_string(v) + ": " + (std::isfinite(q.x) ? "y" : "x") +
                           " coordinate is not finite");
      }
      if (kept == 0 || !(q == ring[kept - 1])) ring[kept++] = q;
    }
    while (kept > 1 && ring[kept - 1] == ring[0]) --kept;
    ring.resize(kept);
    p.rings.push_back(std::move(ring));
  }
  return p;
}

py::array_t<double> ring_array(const std::vector<Point>& ring, bool closed) {
  const std::size_t n = ring.size() + (closed && !ring.empty() ? 1 : 0);
  // The array's memory comes from the extension's allocator (memory.cpp): a large ring
  // reuses a block kept from an earlier call instead of faulting fresh pages in. The
  // capsule frees it with the array.
  std::unique_ptr<double[]> data(new double[2 * std::max<std::size_t>(n, 1)]);
  double* out = data.get();
  static_assert(sizeof(Point) == 2 * sizeof(double));
  if (!ring.empty()) std::memcpy(out, static_cast<const void*>(ring.data()), ring.size() * sizeof(Point));
  if (n > ring.size()) {
    out[2 * ring.size()] = ring.front().x;
    out[2 * ring.size() + 1] = ring.front().y;
  }
  py::capsule owner(data.get(), [](void* p) { delete[] static_cast<double*>(p); });
  data.release();
  return py::array_t<double>({static_cast<py::ssize_t>(n), py::ssize_t{2}}, out, owner);
}

void bind_convert(py::module_& m) {
  py::class_<InputPolygon>(m, "InputPolygon",
                           "A polygon as the library takes it: rings (the paper's form, no closing vertex) "
                           "and a type, island or hole.")
      .def_property_readonly("type", [](const InputPolygon& p) { return type_name(p.polygon->type); })
      .def_property_readonly("is_exact", [](const InputPolygon& p) { return p.exact != nullptr; },
                             "Whether some coordinate is not a double (then .rings holds the nearest doubles)")
      .def_property_readonly("rings", [](const InputPolygon& p) { return ring_list(*p.polygon); })
      .def_property_readonly("vertex_count", [](const InputPolygon& p) {
        std::size_t n = 0;
        for (const Ring& r : p.polygon->rings) n += r.size();
        return n;
      })
      .def("__repr__", [](const InputPolygon& p) {
        std::size_t n = 0;
        for (const Ring& r : p.polygon->rings) n += r.size();
        return "<mkbool.InputPolygon " + type_name(p.polygon->type) + ": " + std::to_string(p.polygon->rings.size()) +
               " rings, " + std::to_string(n) + " vertices" + (p.exact ? ", exact" : "") + ">";
      });

  m.def("from_arrays", [](const py::sequence& rings, const std::string& type) {
    return shared(polygon_from_arrays(rings, type_named(type)));
  }, py::arg("rings"), py::arg("type") = "island");
  m.def("from_exact", [](const std::vector<std::vector<std::string>>& rings, const std::string& type) {
    return input_from_exact(exact_from_texts(rings, type_named(type)));
  }, py::arg("rings"), py::arg("type") = "island");
  // WKT, GeoJSON or native JSON, sniffed as the command does for inline text; native JSON's
  // coordinates that are not doubles are kept exactly.
  m.def("from_text", [](const std::string& text) {
    PolygonInput in = read_polygon_input(text, "");
    if (in.exact) return input_from_exact(std::move(*in.exact));
    return shared(std::move(in.polygon));
  }, py::arg("text"));
  m.def("from_wkt", [](const std::string& text) {
    PartNames names;
    const MultiPolygon mp = read_wkt(text, &names.parts);
    return shared(to_checked_polygon(mp, names));
  }, py::arg("text"));
  m.def("from_wkb", [](const py::buffer& bytes) {
    PartNames names;
    const MultiPolygon mp = read_wkb(buffer_bytes(bytes), &names.parts);
    return shared(to_checked_polygon(mp, names));
  }, py::arg("wkb"));
  m.def("from_result", &input_from_result, py::arg("result"));
}

}  // namespace mk::python
