// The command's heap: freed memory kept for the next phase, and address space reserved at
// the heap's top with the advice that it be backed by huge pages, so that an operation's
// arrays fault in 2 MB at a time instead of 4 KB. A page fault costs 1-11 µs on the virtual
// machines of bench/README.md ("The command's heap"), and an operation on 10^5 vertices
// touches tens of megabytes: before this, faults were half the command's time there.
// [BRIEF §6] (what the user waits for)
// Preconditions: called first thing in main, before any thread is started; for a process
// that runs operations and exits (the library leaves the process's allocator alone).
#pragma once

#include <cstddef>
#include <cstdint>

namespace mk::cli {

// What prepare_heap did: the reserved range (aligned to 2 MB; empty when nothing was
// reserved) and whether the kernel took the advice.
struct HeapReservation {
  std::uintptr_t begin = 0, end = 0;
  bool huge_pages = false;
};

// The default reservation: virtual address space only; what is never touched costs nothing.
inline constexpr std::size_t kHeapReservation = std::size_t{1} << 30;

// With glibc: freed memory stays in the heap (no separate maps for large blocks, no trim),
// every thread allocates from that one heap, and `bytes` at its top are reserved and
// advised for huge pages. Nothing is reserved under AddressSanitizer (its own allocator
// would poison the whole range) or when the kernel refuses to overcommit (the reservation
// would count against the process's memory). Without glibc, nothing.
HeapReservation prepare_heap(std::size_t bytes = kHeapReservation);

}  // namespace mk::cli
