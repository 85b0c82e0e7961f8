// arena.cpp - the HAL memory block (mmap'd once, zeroed, bump allocation).
#include "arena.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <cstring>
#include <new>

namespace firtp::hal_shim::detail {

void Arena::init(std::size_t bytes) {
  if (base_ != nullptr) return;
  void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  base_ = static_cast<std::byte*>(p);
  capacity_ = bytes;
  used_ = 0;
}

void* Arena::alloc(std::size_t size, std::size_t align) {
  const auto start = reinterpret_cast<std::uintptr_t>(base_);
  std::uintptr_t at = (start + used_ + align - 1) & ~(static_cast<std::uintptr_t>(align) - 1);
  std::size_t offset = at - start;
  if (base_ == nullptr || offset > capacity_ || size > capacity_ - offset) return nullptr;
  used_ = offset + size;
  return base_ + offset;
}

bool Arena::contains(const void* p, std::size_t size) const {
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  const auto start = reinterpret_cast<std::uintptr_t>(base_);
  return base_ != nullptr && at >= start && size <= capacity_ && at - start <= capacity_ - size;
}

void Arena::rewind() {
  if (base_ != nullptr) std::memset(base_, 0, used_);
  used_ = 0;
}

}  // namespace firtp::hal_shim::detail
