// The command's heap: freed memory kept, the top advised for huge pages. [BRIEF §6]
// Preconditions: see heap.hpp.
#include "cli/heap.hpp"

#include <climits>
#include <cstdlib>
#include <fstream>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
#define MK_HEAP_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MK_HEAP_ASAN 1
#endif
#endif

namespace mk::cli {

#if defined(__GLIBC__) && !defined(MK_HEAP_ASAN)
namespace {

// Whether the kernel counts every mapping against a commit limit (vm.overcommit_memory 2).
bool strict_overcommit() {
  std::ifstream in("/proc/sys/vm/overcommit_memory");
  std::string mode;
  return in >> mode && mode == "2";
}

}  // namespace
#endif

HeapReservation prepare_heap(std::size_t bytes) {
  HeapReservation h;
#if defined(__GLIBC__)
  // glibc maps each block over its threshold (up to 32 MB) on its own and unmaps it when
  // freed, and trims the heap's top: an operation's phases faulted their arrays in again and
  // again (blob 1e6: 157k page faults against 68k).
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
  // The pool's threads would each get an arena of their own, mapped apart from the heap and
  // not advised: one arena for all (the operation's threads allocate a few large arrays,
  // not many small ones; measured faster on two cores, bench/README.md).
  mallopt(M_ARENA_MAX, 1);
#if !defined(MK_HEAP_ASAN)
  if (bytes == 0 || bytes >= static_cast<std::size_t>(INT_MAX) || strict_overcommit()) return h;
  // A block of `bytes` from the top of the heap (M_MMAP_MAX 0: never a map of its own),
  // freed at once: it merges into the top and stays there (no trim), never touched.
  void* const block = std::malloc(bytes);
  if (block == nullptr) return h;
  const auto at = reinterpret_cast<std::uintptr_t>(block);
  constexpr std::uintptr_t huge = std::uintptr_t{2} << 20;
  h.begin = (at + huge - 1) & ~(huge - 1);
  h.end = (at + bytes) & ~(huge - 1);
  std::free(block);
  if (h.end <= h.begin) {
    h.begin = h.end = 0;
    return h;
  }
  h.huge_pages = madvise(reinterpret_cast<void*>(h.begin), h.end - h.begin, MADV_HUGEPAGE) == 0;
#else
  (void)bytes;
#endif
#else
  (void)bytes;
#endif
  return h;
}

}  // namespace mk::cli
