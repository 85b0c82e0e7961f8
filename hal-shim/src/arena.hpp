// arena.hpp - the HAL memory: one fixed block, bump-allocated, never freed while running.
#pragma once

#include <cstddef>

namespace firtp::hal_shim::detail {

/// A fixed block of zeroed memory handed out front to back (like HAL shared memory).
class Arena {
 public:
  /// Maps 'bytes' of zeroed memory; only the first call has an effect.
  void init(std::size_t bytes);
  /// Returns 'size' bytes aligned to 'align' (a power of two), or nullptr when full.
  void* alloc(std::size_t size, std::size_t align = 16);
  /// True when [p, p+size) lies inside the block.
  [[nodiscard]] bool contains(const void* p, std::size_t size = 1) const;
  /// Zeroes the used part and starts over (only when nothing references it any more).
  void rewind();
  [[nodiscard]] std::size_t used() const { return used_; }
  [[nodiscard]] std::size_t capacity() const { return capacity_; }

 private:
  std::byte* base_ = nullptr;
  std::size_t capacity_ = 0;
  std::size_t used_ = 0;
};

}  // namespace firtp::hal_shim::detail
