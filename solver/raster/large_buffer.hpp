// The allocator of image-sized buffers (a frame's colours and depths): a buffer of 2 MiB or
// more is aligned to 2 MiB and marked for transparent huge pages (madvise MADV_HUGEPAGE, which
// the kernel honours when transparent huge pages are set to `madvise` or `always`). A fresh
// 1920 × 1080 frame is then 8 page faults instead of 4,000, which on a small scene are a large
// share of `frustum render`'s time; smaller buffers are allocated as usual.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>

namespace frustum {

template <typename T>
struct LargeBufferAllocator {
  using value_type = T;
  static constexpr std::size_t kHugePage = std::size_t(2) << 20;

  LargeBufferAllocator() = default;
  template <typename U>
  LargeBufferAllocator(const LargeBufferAllocator<U>&) {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePage || alignof(T) > kHugePage)
      return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (!p) throw std::bad_alloc();
    madvise(p, rounded, MADV_HUGEPAGE);  // advice only: without huge pages it is ignored
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePage || alignof(T) > kHugePage)
      ::operator delete(p, std::align_val_t(alignof(T)));
    else
      std::free(p);
  }
  // resize() leaves new pixels default-initialised (indeterminate for numbers), so that a
  // frame whose every pixel is written next (fill_in_bands clears each band itself) is not
  // written twice; construction from a value is as usual.
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <typename U>
  bool operator==(const LargeBufferAllocator<U>&) const noexcept {
    return true;
  }
};

}  // namespace frustum
