// The extension's own operator new and delete: large blocks (256 KiB and more) that the
// library frees are kept for the next call instead of going back to the system, up to a
// limit (256 MiB unless set). A Python process runs many operations one after the other,
// and glibc hands a freed large block back to the kernel (munmap, or a trim of the heap's
// top) after each call; the next call then faults every page in again, zeroed, which on
// the measured machine cost about a quarter of an operation on blob 1e5 (bench/README.md).
// Allocators such as jemalloc and tcmalloc keep freed memory likewise.
//
// The definitions are local to the extension (python/exports.map exports PyInit__mkbool
// alone): they serve the code linked into _mkbool (the library, io, the harness,
// pybind11's templates) and leave the interpreter, numpy and shapely on their own
// allocator. Every block is a malloc block, so a block allocated here and freed by code
// outside (libstdc++'s compiled members call the process's operator delete, which calls
// free) is simply freed, and a block allocated outside and freed here is cached or freed by
// its usable size.
// Preconditions: glibc (malloc_usable_size); not linked into sanitizer builds, whose
// runtime replaces the allocator.
#include <malloc.h>
#include <pthread.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>

#include "module.hpp"

namespace mk::python {

namespace {

constexpr std::size_t kLarge = std::size_t{256} << 10;

class BlockCache {
 public:
  // A kept block of at least n usable bytes and not more than twice that, or nullptr.
  void* take(std::size_t n) {
    const std::lock_guard lock(mutex_);
    std::size_t best = kSlots;
    for (std::size_t i = 0; i < count_; ++i) {
      const std::size_t size = blocks_[i].size;
      if (size >= n && size / 2 <= n && (best == kSlots || size < blocks_[best].size)) best = i;
    }
    if (best == kSlots) return nullptr;
    void* p = blocks_[best].p;
    cached_ -= blocks_[best].size;
    blocks_[best] = blocks_[--count_];
    return p;
  }

  // Keeps the block if there is room, else frees it.
  void give(void* p, std::size_t size) {
    {
      const std::lock_guard lock(mutex_);
      if (count_ < kSlots && cached_ + size <= limit_) {
        blocks_[count_++] = {p, size};
        cached_ += size;
        return;
      }
    }
    std::free(p);
  }

  void set_limit(std::size_t bytes) {
    {
      const std::lock_guard lock(mutex_);
      limit_ = bytes;
    }
    trim_to_limit();
  }

  // Frees kept blocks, largest first, until their total fits both `limit` and the cache's
  // limit.
  void trim_to_limit(std::size_t limit = SIZE_MAX) {
    for (;;) {
      void* p = nullptr;
      {
        const std::lock_guard lock(mutex_);
        const std::size_t keep = limit < limit_ ? limit : limit_;
        if (cached_ <= keep || count_ == 0) return;
        std::size_t largest = 0;
        for (std::size_t i = 1; i < count_; ++i) {
          if (blocks_[i].size > blocks_[largest].size) largest = i;
        }
        p = blocks_[largest].p;
        cached_ -= blocks_[largest].size;
        blocks_[largest] = blocks_[--count_];
      }
      std::free(p);
    }
  }

  // Around fork(): the child gets the cache unlocked and consistent even when another thread
  // of the parent was inside it (Python's multiprocessing forks threaded processes).
  void lock() { mutex_.lock(); }
  void unlock() { mutex_.unlock(); }

  MemoryCacheState state() {
    const std::lock_guard lock(mutex_);
    return {cached_, count_, limit_};
  }

 private:
  static constexpr std::size_t kSlots = 64;
  struct Block {
    void* p = nullptr;
    std::size_t size = 0;
  };
  std::mutex mutex_;
  std::array<Block, kSlots> blocks_{};
  std::size_t count_ = 0;
  std::size_t cached_ = 0;
  std::size_t limit_ = std::size_t{256} << 20;
};

// Never destroyed: blocks are freed through it during and after static destruction.
BlockCache& cache() {
  alignas(BlockCache) static unsigned char storage[sizeof(BlockCache)];
  static BlockCache* c = [] {
    auto* made = new (storage) BlockCache;
    pthread_atfork([] { cache().lock(); }, [] { cache().unlock(); }, [] { cache().unlock(); });
    return made;
  }();
  return *c;
}

void* allocate(std::size_t n) {
  if (n >= kLarge) {
    if (void* p = cache().take(n)) return p;
  }
  for (;;) {
    if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

void* allocate_or_null(std::size_t n) noexcept {
  try {
    return allocate(n);
  } catch (...) {
    return nullptr;
  }
}

void release(void* p) noexcept {
  if (p == nullptr) return;
  const std::size_t size = malloc_usable_size(p);
  if (size >= kLarge) {
    cache().give(p, size);
  } else {
    std::free(p);
  }
}

}  // namespace

MemoryCacheState memory_cache_state() { return cache().state(); }
void set_memory_cache_limit(std::size_t bytes) { cache().set_limit(bytes); }
void release_memory_cache() { cache().trim_to_limit(0); }

}  // namespace mk::python

void* operator new(std::size_t n) { return mk::python::allocate(n); }
void* operator new[](std::size_t n) { return mk::python::allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return mk::python::allocate_or_null(n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return mk::python::allocate_or_null(n); }
void operator delete(void* p) noexcept { mk::python::release(p); }
void operator delete[](void* p) noexcept { mk::python::release(p); }
void operator delete(void* p, std::size_t) noexcept { mk::python::release(p); }
void operator delete[](void* p, std::size_t) noexcept { mk::python::release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { mk::python::release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { mk::python::release(p); }
