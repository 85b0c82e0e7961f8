// rtapi_shmem.cpp - rtapi_init/exit and in-process shared memory blocks found by key.
#include <cstdlib>
#include <cstring>

#include "state.hpp"

using namespace firtp::hal_shim::detail;

namespace firtp::hal_shim::detail {

void shmem_clear() {
  for (auto& [id, block] : state().shmem) std::free(block.ptr);
  state().shmem.clear();
}

}  // namespace firtp::hal_shim::detail

extern "C" {

int rtapi_init(const char* /*modname*/) {
  State& s = state();
  Lock lock(s.mu);
  return s.next_id++;
}

int rtapi_exit(int module_id) { return module_id > 0 ? 0 : -EINVAL; }

int rtapi_shmem_new(int key, int module_id, unsigned long int size) {
  State& s = state();
  Lock lock(s.mu);
  if (key == 0 || module_id <= 0 || size == 0) return -EINVAL;
  for (auto& [id, block] : s.shmem) {
    if (block.key != key) continue;
    if (size > block.size) {
      rtapi_print_msg(RTAPI_MSG_ERR, "RTAPI: ERROR: shmem key %d is %zu bytes, %lu requested\n",
                      key, block.size, size);
      return -EINVAL;
    }
    ++block.refs;
    return id;
  }
  const std::size_t rounded = (size + 63) & ~std::size_t{63};
  void* p = std::aligned_alloc(64, rounded);
  if (p == nullptr) return -ENOMEM;
  std::memset(p, 0, rounded);
  Shmem block;
  block.id = s.next_shmem_id++;
  block.key = key;
  block.refs = 1;
  block.size = size;
  block.ptr = p;
  s.shmem[block.id] = block;
  return block.id;
}

int rtapi_shmem_delete(int shmem_id, int /*module_id*/) {
  State& s = state();
  Lock lock(s.mu);
  auto it = s.shmem.find(shmem_id);
  if (it == s.shmem.end()) return -EINVAL;
  if (--it->second.refs == 0) {
    std::free(it->second.ptr);
    s.shmem.erase(it);
  }
  return 0;
}

int rtapi_shmem_getptr(int shmem_id, void** ptr) {
  State& s = state();
  Lock lock(s.mu);
  auto it = s.shmem.find(shmem_id);
  if (it == s.shmem.end() || ptr == nullptr) return -EINVAL;
  *ptr = it->second.ptr;
  return 0;
}

int rtapi_is_kernelspace(void) { return 0; }

int rtapi_is_realtime(void) {
  State& s = state();
  Lock lock(s.mu);
  return s.rt_priority > 0 ? 1 : 0;
}

}  // extern "C"
