// libFuzzer target for the whole operation: two polygons decoded from the bytes
// (fuzz/operation_bytes.hpp), every operation, regular and non-regular, under the exact and
// rational kernels; no crash, no sanitizer report, and the two kernels agree exactly (the
// same error for input outside the domain, else the same result polygons, types, exact
// coordinates, area and written output); certified rounding never fails its self-check and
// writes a valid output. Each result also goes through every writer.
// [MK89 §3.1] (the six steps) [MK89 §2.3] (operations) [BRIEF §3] (exact kernels agree)
// Preconditions: built by fuzz/run.sh (clang, -fsanitize=fuzzer,address,undefined).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "api/mkbool.hpp"
#include "fuzz/operation_bytes.hpp"
#include "io/geojson.hpp"
#include "io/native_json.hpp"
#include "io/svg.hpp"
#include "io/wkt.hpp"

namespace {

// What must be equal between exact kernels: an error message, or the result up to the
// order of its irreducible polygons and the start of each cycle.
struct Outcome {
  std::string error;
  std::vector<std::string> cycles;  // type and exact coordinates, rotated to a canonical start
  std::vector<std::string> extras;  // dangling edges, isolated points, flags, area
};

std::string canonical_cycle(const mk::OutputIrreducible& c) {
  const std::size_t n = c.vertices.size();
  std::vector<std::string> pairs(n);
  for (std::size_t i = 0; i < n; ++i) pairs[i] = c.exact.at(2 * i) + " " + c.exact.at(2 * i + 1);
  const auto first = static_cast<std::ptrdiff_t>(std::min_element(pairs.begin(), pairs.end()) - pairs.begin());
  std::rotate(pairs.begin(), pairs.begin() + first, pairs.end());
  std::string s = c.type == mk::PolygonType::island ? "island:" : "hole:";
  for (const auto& p : pairs) s += " " + p;
  return s;
}

std::string point_text(const mk::Point& p) { return std::to_string(p.x) + " " + std::to_string(p.y); }

Outcome run(const mk::fuzz::DecodedCase& c, const char* kernel) {
  Outcome o;
  mk::BooleanOptions options;
  options.op = c.op;
  options.regular = c.regular;
  options.kernel = kernel;
  options.exact_coordinates = true;  // compared below
  // Certified rounding (the default): where the nearest doubles are not valid the written
  // output is a snap rounding, which must be valid, free of self-check failures, and the
  // same for both kernels (it depends on the exact result only).
  options.area_exact = true;
  try {
    const mk::BooleanOutput r = mk::compute(c.a, c.b, options);
    for (const auto& cycle : r.output.irreducible) o.cycles.push_back(canonical_cycle(cycle));
    std::sort(o.cycles.begin(), o.cycles.end());
    for (const auto& [p, q] : r.output.dangling_edges) o.extras.push_back("edge " + point_text(p) + " " + point_text(q));
    for (const auto& p : r.output.isolated_points) o.extras.push_back("point " + point_text(p));
    std::sort(o.extras.begin(), o.extras.end());
    o.extras.push_back(r.output.unbounded ? "unbounded" : "bounded");
    o.extras.push_back(r.output.rounded_valid.value_or(false) ? "valid" : "invalid");
    o.extras.push_back("area " + r.stats.area_exact.value_or("none"));
    const mk::RoundingReport& rounding = r.output.rounding;
    if (!rounding.failure.empty()) {
      std::fprintf(stderr, "%s: certified rounding failed: %s\n", kernel, rounding.failure.c_str());
      __builtin_trap();
    }
    if (!rounding.valid && !r.output.unbounded) {
      std::fprintf(stderr, "%s: certified rounding wrote an invalid output\n", kernel);
      __builtin_trap();
    }
    o.extras.push_back(rounding.snapped ? "snapped " + rounding.grid : "nearest");
    // The written polygons (the snap rounding when snapped), as text.
    if (!r.output.unbounded) o.extras.push_back(mk::write_wkt(r.output));
    // Every writer takes every result (WKT and GeoJSON refuse unbounded ones by name).
    (void)mk::write_native_json(r.output, r.stats.kernel);
    (void)mk::write_svg(c.a, c.b, r.output);
    if (!r.output.unbounded) {
      (void)mk::write_wkt(r.output);
      (void)mk::write_geojson(r.output);
    }
  } catch (const mk::InvalidInput& e) {
    o.error = e.what();
  }
  return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mk::fuzz::DecodedCase c = mk::fuzz::decode_case(data, size);
  // The operation and regularity in the bytes come first; the others follow, so that every
  // input exercises all eight.
  for (int k = 0; k < 8; ++k) {
    mk::fuzz::DecodedCase variant = c;
    variant.op = static_cast<mk::Operation>((static_cast<int>(c.op) + k / 2) % 4);
    variant.regular = (k % 2 == 0) == c.regular;
    const Outcome exact = run(variant, "exact");
    const Outcome rational = run(variant, "rational");
    if (exact.error != rational.error || exact.cycles != rational.cycles || exact.extras != rational.extras) {
      std::fprintf(stderr, "exact and rational kernels disagree on %s (%s)\n  exact: %s\n  rational: %s\n",
                   std::string(mk::operation_name(variant.op)).c_str(), variant.regular ? "regular" : "non-regular",
                   exact.error.empty() ? "a result" : exact.error.c_str(),
                   rational.error.empty() ? "a result" : rational.error.c_str());
      __builtin_trap();
    }
  }
  return 0;
}
