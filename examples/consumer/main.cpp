// A project outside mkbool using the installed package: A minus B, computed as A intersected
// with B taken as a hole. [MK89 §2.2] (island and hole regions)
// Preconditions: mkbool installed (cmake --install) where find_package(mkbool) looks.
#include <cstdio>
#include "api/mkbool.hpp"

int main() {
  const mk::Polygon a{{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, mk::PolygonType::island};
  const mk::Polygon b{{{{1, 1}, {3, 1}, {3, 3}, {1, 3}}}, mk::PolygonType::hole};
  try {
    const mk::BooleanOutput r = mk::compute(a, b, {.op = mk::Operation::intersection, .kernel = "exact", .area_exact = true});
    for (const mk::OutputIrreducible& p : r.output.irreducible)
      std::printf("%s, %zu vertices\n", p.type == mk::PolygonType::island ? "island" : "hole", p.vertices.size());
    std::printf("area %s\n", r.stats.area_exact->c_str());  // exact kernels: "p/q" or "p"
  } catch (const mk::InvalidInput& e) {  // malformed or outside the domain; names where
    std::fprintf(stderr, "invalid input: %s\n", e.what());
    return 3;
  }
}
