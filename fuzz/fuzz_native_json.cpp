// libFuzzer target for the native JSON reader and writer: any input either parses or throws
// mk::InvalidInput, and whatever parses reads back identically (same type, same points).
// [MK89 §2.2]
// Preconditions: built by fuzz/run.sh (clang, -fsanitize=fuzzer,address,undefined).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "io/native_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const mk::Polygon p = mk::read_native_json(text);
    const mk::Polygon back = mk::read_native_json(mk::write_native_json(p));
    if (back.type != p.type || back.rings != p.rings) __builtin_trap();
  } catch (const mk::InvalidInput&) {
    // Rejected with a message: the expected outcome for malformed input.
  }
  return 0;
}
