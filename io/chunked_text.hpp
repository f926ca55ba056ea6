// A large text written in chunks on several threads and joined in order: one thread appends
// finished chunks to the result (and formats the next chunk itself when it is the next to
// append) while the others format the chunks after it, so joining overlaps formatting. The
// same bytes on any number of threads. [BRIEF §6] (across cores)
// Preconditions: format(i, out) writes chunk i's text at `out` and returns its end, writing
// at most bound(i) bytes past out, reading nothing that changes meanwhile; it may throw.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#endif

#include "core/parallel.hpp"

namespace mk::io_detail {

// Fresh pages of a large text cost more than writing its bytes (a fault and a cleared page
// per 4 kB: 15 of blob 1e6's 35 MB text's first 50 ms): asks for 2 MB pages where the kernel
// gives them on request (Linux's transparent huge pages in "madvise" mode). Only a hint: a
// refusal changes nothing.
inline void advise_huge_pages([[maybe_unused]] char* data, [[maybe_unused]] std::size_t size) {
#ifdef __linux__
  constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
  if (size < 4 * kHuge) return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + size) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
}

// Chunks are formatted into a scratch buffer of the largest bound (kept in cache, grown at
// most once per thread), then appended to the result or kept for it.
template <class Bound, class Format>
std::string join_chunks(std::size_t chunks, unsigned threads, Bound&& bound, Format&& format) {
  std::size_t total = 0, largest = 0;
  for (std::size_t i = 0; i < chunks; ++i) {
    total += bound(i);
    largest = std::max(largest, bound(i));
  }
  std::string out;
  out.reserve(total + 1);  // the bytes stay untouched (and unpaid for) past the text's end;
                           // the 1: the final newline the command adds
  advise_huge_pages(out.data(), out.capacity());
  struct Done {
    std::string text;
    std::exception_ptr error;
    std::atomic<bool> ready{false};
  };
  const std::unique_ptr<Done[]> done(new Done[chunks]);
  std::atomic<std::size_t> next_claim{0};
  // Texts kept for the appender reuse the buffers of texts already appended: fresh pages
  // for every chunk cost more than formatting it.
  std::mutex spare_mutex;
  std::vector<std::string> spare;
  const auto keep = [&](std::size_t i, const std::string& scratch, std::size_t size) {
    std::string text;
    {
      const std::lock_guard<std::mutex> lock(spare_mutex);
      if (!spare.empty()) {
        text = std::move(spare.back());
        spare.pop_back();
      }
    }
    text.assign(scratch.data(), size);
    done[i].text = std::move(text);
  };
  const auto format_into = [&](std::string& scratch, std::size_t i) -> std::size_t {
    if (scratch.size() < largest) scratch.resize(largest);
    return static_cast<std::size_t>(format(i, scratch.data()) - scratch.data());
  };
  // Formats claimed chunks for the appender; stops at its first failure, which the appender
  // rethrows when it reaches that chunk.
  const auto helper = [&] {
    std::string scratch;
    for (std::size_t i = next_claim++; i < chunks; i = next_claim++) {
      try {
        keep(i, scratch, format_into(scratch, i));
      } catch (...) {
        done[i].error = std::current_exception();
      }
      done[i].ready.store(true, std::memory_order_release);
      done[i].ready.notify_one();
      if (done[i].error) return;
    }
  };
  const auto appender = [&] {
    std::string scratch;
    std::size_t next = 0;  // the next chunk to append
    while (next < chunks) {
      if (done[next].ready.load(std::memory_order_acquire)) {
        if (done[next].error) std::rethrow_exception(done[next].error);
        out += done[next].text;
        {
          const std::lock_guard<std::mutex> lock(spare_mutex);
          spare.push_back(std::move(done[next].text));
        }
        ++next;
        continue;
      }
      const std::size_t i = next_claim++;
      if (i == next) {
        out.append(scratch.data(), format_into(scratch, i));
        ++next;
      } else if (i < chunks) {
        keep(i, scratch, format_into(scratch, i));
        done[i].ready.store(true, std::memory_order_release);
      } else {
        done[next].ready.wait(false, std::memory_order_acquire);
      }
    }
  };
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(std::max(1u, threads), chunks));
  run_tasks(workers, workers, [&](std::size_t task) {
    if (task == 0) {
      appender();
    } else {
      helper();
    }
  });
  return out;
}

}  // namespace mk::io_detail
