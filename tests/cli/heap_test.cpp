// The command's heap (cli/heap.hpp): the reserved range is aligned to huge pages, the
// blocks allocated after it come from it (not from maps of their own, where the advice
// would not reach), and the kernel takes the advice wherever it has transparent huge
// pages; under AddressSanitizer nothing is reserved. Run in a child process: the
// reservation changes the allocator for the rest of the process.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "cli/heap.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define MK_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MK_TEST_ASAN 1
#endif
#endif

namespace mk::cli {
namespace {

#if !defined(MK_TEST_ASAN)
// Whether the kernel gives transparent huge pages at all ("always" or "madvise").
bool kernel_has_huge_pages() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  return std::getline(in, line) && line.find("[never]") == std::string::npos;
}
#endif

// The child's findings as its exit code: 0 when all hold.
int check_reservation() {
  const HeapReservation h = prepare_heap(std::size_t{64} << 20);
#if defined(MK_TEST_ASAN)
  return h.begin == h.end && !h.huge_pages ? 0 : 1;
#else
  constexpr std::uintptr_t huge = std::uintptr_t{2} << 20;
  if (!(h.begin < h.end)) return 2;
  if (h.begin % huge != 0 || h.end % huge != 0) return 3;
  if (h.end - h.begin < (std::uintptr_t{62} << 20)) return 4;  // 64 MB less alignment
  const std::size_t size = std::size_t{32} << 20;
  char* const block = static_cast<char*>(std::malloc(size));
  if (block == nullptr) return 5;
  const auto at = reinterpret_cast<std::uintptr_t>(block);
  if (at + huge < h.begin || at + size > h.end + huge) return 6;  // within the reservation
  for (std::size_t i = 0; i < size; i += 4096) block[i] = 1;
  std::free(block);
  if (h.huge_pages != kernel_has_huge_pages()) return 7;
  return 0;
#endif
}

TEST(CommandHeap, ReservedTopAlignedReusedAndAdvised) {
  EXPECT_EXIT(std::exit(check_reservation()), ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace mk::cli
