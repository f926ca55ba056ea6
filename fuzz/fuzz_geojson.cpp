// libFuzzer target for the GeoJSON reader and writer: any input either parses or throws
// mk::InvalidInput, and whatever parses reads back identically after write_geojson.
// [RFC7946 §3]
// Preconditions: built by fuzz/run.sh (clang, -fsanitize=fuzzer,address,undefined).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "io/format.hpp"
#include "io/geojson.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const mk::MultiPolygon mp = mk::read_geojson(text);
    const mk::MultiPolygon back = mk::read_geojson(mk::write_geojson(mp));
    if (back.size() != mp.size()) __builtin_trap();
    for (std::size_t i = 0; i < mp.size(); ++i) {
      if (back[i].shell.size() != mp[i].shell.size()) __builtin_trap();
      if (back[i].holes.size() != mp[i].holes.size()) __builtin_trap();
    }
  } catch (const mk::InvalidInput&) {
    // Rejected with a message: the expected outcome for malformed input.
  }
  try {
    // As the command reads it: with the multi-part check (io/parts.hpp).
    (void)mk::read_polygon_input(text, "a.geojson");
  } catch (const mk::InvalidInput&) {
  }
  return 0;
}
