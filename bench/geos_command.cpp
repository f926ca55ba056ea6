// geos_command OP A.wkt B.wkt OUT.wkt: what `mkbool OP A.wkt B.wkt -o OUT.wkt` does, with
// GEOS: read both files as WKT, run the overlay, write the result as WKT with 17 significant
// digits (enough to round-trip every double, as mkbool writes them) to OUT.wkt. The
// peer's side of the end-to-end comparison (bench/end_to_end.sh, issue 17).
// Preconditions: GEOS's C API; both files hold one polygonal WKT geometry each.
#include <geos_c.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

std::string slurp(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(std::string("cannot read ") + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: geos_command intersection|union|difference|xor A.wkt B.wkt OUT.wkt\n";
    return 2;
  }
  const std::string op = argv[1];
  const auto t0 = std::chrono::steady_clock::now();
  GEOSContextHandle_t h = GEOS_init_r();
  GEOSWKTReader* reader = GEOSWKTReader_create_r(h);
  GEOSGeometry* a = GEOSWKTReader_read_r(h, reader, slurp(argv[2]).c_str());
  GEOSGeometry* b = GEOSWKTReader_read_r(h, reader, slurp(argv[3]).c_str());
  if (!a || !b) {
    std::cerr << "geos_command: GEOS could not read the input\n";
    return 3;
  }
  const auto t1 = std::chrono::steady_clock::now();
  GEOSGeometry* r = op == "intersection" ? GEOSIntersection_r(h, a, b)
                    : op == "union"      ? GEOSUnion_r(h, a, b)
                    : op == "difference" ? GEOSDifference_r(h, a, b)
                                         : GEOSSymDifference_r(h, a, b);
  if (!r) {
    std::cerr << "geos_command: GEOS failed\n";
    return 1;
  }
  const auto t2 = std::chrono::steady_clock::now();
  GEOSWKTWriter* writer = GEOSWKTWriter_create_r(h);
  GEOSWKTWriter_setTrim_r(h, writer, 1);
  GEOSWKTWriter_setRoundingPrecision_r(h, writer, 17);
  char* text = GEOSWKTWriter_write_r(h, writer, r);
  {
    std::ofstream out(argv[4], std::ios::binary);
    out << text << "\n";
    if (!out) {
      std::cerr << "geos_command: cannot write " << argv[4] << "\n";
      return 1;
    }
  }
  const auto t3 = std::chrono::steady_clock::now();
  const auto s = [](auto d) { return std::chrono::duration<double>(d).count(); };
  std::fprintf(stderr, "{\"read_s\":%.4f,\"op_s\":%.4f,\"write_s\":%.4f}\n", s(t1 - t0), s(t2 - t1), s(t3 - t2));
  GEOSFree_r(h, text);
  GEOSWKTWriter_destroy_r(h, writer);
  GEOSGeom_destroy_r(h, r);
  GEOSGeom_destroy_r(h, a);
  GEOSGeom_destroy_r(h, b);
  GEOSWKTReader_destroy_r(h, reader);
  GEOS_finish_r(h);
  return 0;
}
