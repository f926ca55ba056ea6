// libFuzzer target for the WKT reader and writer: any input either parses or throws
// mk::InvalidInput, and whatever parses survives write_wkt / read_wkt unchanged in shape;
// the command's reading (with the multi-part check) only ever throws mk::InvalidInput.
// [OGC06-103 §7]
// Preconditions: built by fuzz/run.sh (clang, -fsanitize=fuzzer,address,undefined).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "io/format.hpp"
#include "io/wkt.hpp"

namespace {

// The written text describes the same rings (the writer may reverse a ring, so only the
// sizes and the set of polygons are compared); any difference is a bug, so it crashes.
void check_round_trip(const mk::MultiPolygon& mp) {
  const mk::MultiPolygon back = mk::read_wkt(mk::write_wkt(mp));
  if (back.size() != mp.size()) __builtin_trap();
  for (std::size_t i = 0; i < mp.size(); ++i) {
    if (back[i].shell.size() != mp[i].shell.size()) __builtin_trap();
    if (back[i].holes.size() != mp[i].holes.size()) __builtin_trap();
    for (std::size_t h = 0; h < mp[i].holes.size(); ++h) {
      if (back[i].holes[h].size() != mp[i].holes[h].size()) __builtin_trap();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  (void)mk::sniff_format(text, "");
  try {
    check_round_trip(mk::read_wkt(text));
  } catch (const mk::InvalidInput&) {
    // Rejected with a message: the expected outcome for malformed text.
  }
  try {
    // As the command reads it: with the multi-part check (io/parts.hpp).
    (void)mk::read_polygon_input(text, "a.wkt");
  } catch (const mk::InvalidInput&) {
  }
  return 0;
}
