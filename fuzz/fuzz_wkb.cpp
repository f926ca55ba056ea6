// libFuzzer target for the WKB reader and writer: any byte string either parses or throws
// mk::InvalidInput, and whatever parses survives write_wkb / read_wkb bit for bit in its
// coordinates (the writer may only turn a ring around).
// [OGC06-103 §8.2]
// Preconditions: built by fuzz/run.sh (clang, -fsanitize=fuzzer,address,undefined).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "io/wkb.hpp"

namespace {

bool same_points(mk::Ring a, mk::Ring b) {
  const auto less = [](const mk::Point& p, const mk::Point& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); };
  std::sort(a.begin(), a.end(), less);
  std::sort(b.begin(), b.end(), less);
  return a == b;
}

void check_round_trip(const mk::MultiPolygon& mp) {
  const mk::MultiPolygon back = mk::read_wkb(mk::write_wkb(mp));
  if (back.size() != mp.size()) __builtin_trap();
  for (std::size_t i = 0; i < mp.size(); ++i) {
    if (!same_points(back[i].shell, mp[i].shell)) __builtin_trap();
    if (back[i].holes.size() != mp[i].holes.size()) __builtin_trap();
    for (std::size_t h = 0; h < mp[i].holes.size(); ++h) {
      if (!same_points(back[i].holes[h], mp[i].holes[h])) __builtin_trap();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    check_round_trip(mk::read_wkb(bytes));
  } catch (const mk::InvalidInput&) {
    // Rejected with a message: the expected outcome for malformed bytes.
  }
  return 0;
}
