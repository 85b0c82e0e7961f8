// hal_stream.cpp - hal_stream: a lock-free single-producer single-consumer ring of typed records
// in an in-process shared-memory block found by key.  Writer owns 'in', reader owns 'out'; a
// record is published by the release store of 'in' and freed by the release store of 'out'.
#include <csignal>
#include <cstring>
#include <new>

#include "state.hpp"

namespace {

constexpr unsigned kStreamMagic = 0x46535452;  // "FSTR"

}  // namespace

/// Header of a stream's block; the records follow it (each: elements, then its sample number).
struct hal_stream_shm {
  unsigned magic = 0;
  int num_pins = 0;
  unsigned depth = 0;  // slots; depth-1 records fit
  hal_type_t type[HAL_STREAM_MAX_PINS]{};
  alignas(64) std::atomic<unsigned> in{0};  // writer side
  unsigned this_sample = 0;
  std::atomic<unsigned> num_overruns{0};
  alignas(64) std::atomic<unsigned> out{0};  // reader side
  std::atomic<unsigned> num_underruns{0};
};

namespace {

using namespace firtp::hal_shim::detail;

constexpr std::size_t kHeaderBytes = (sizeof(hal_stream_shm) + 63) & ~std::size_t{63};

/// The record area that follows the header.
hal_stream_data* records(hal_stream_shm* f) {
  return reinterpret_cast<hal_stream_data*>(reinterpret_cast<char*>(f) + kHeaderBytes);
}

/// Parses "fbsu..." into types; returns the count or fail(-EINVAL).
int parse_types(const char* text, hal_type_t* types) {
  if (text == nullptr || *text == '\0') return fail(-EINVAL, "stream: empty type string");
  int n = 0;
  for (const char* c = text; *c != '\0'; ++c) {
    if (n == HAL_STREAM_MAX_PINS)
      return fail(-EINVAL, "stream: '%s' has more than %d elements", text, HAL_STREAM_MAX_PINS);
    switch (*c) {
      case 'f': case 'F': types[n++] = HAL_FLOAT; break;
      case 'b': case 'B': types[n++] = HAL_BIT; break;
      case 's': case 'S': types[n++] = HAL_S32; break;
      case 'u': case 'U': types[n++] = HAL_U32; break;
      default:
        return fail(-EINVAL, "stream: unknown type '%c' in '%s' (use f, b, s or u)", *c, text);
    }
  }
  return n;
}

/// Id of the shared-memory block with 'key', or 0.
int block_with_key(int key) {
  for (auto& [id, block] : state().shmem)
    if (block.key == key) return id;
  return 0;
}

unsigned advance(const hal_stream_shm* f, unsigned i) { return i + 1 == f->depth ? 0 : i + 1; }

}  // namespace

extern "C" {

int hal_stream_create(hal_stream_t* stream, int comp, int key, int depth, const char* typestring) {
  State& s = state();
  Lock lock(s.mu);
  if (stream == nullptr) return report(fail(-EINVAL, "stream %d: no hal_stream_t", key));
  hal_type_t types[HAL_STREAM_MAX_PINS];
  const int n = parse_types(typestring, types);
  if (n < 0) return report(n);
  if (depth < 2 || depth > (1 << 26))
    return report(fail(-EINVAL, "stream %d: depth %d is not in 2..2^26", key, depth));
  if (block_with_key(key) != 0) return report(fail(-EEXIST, "stream key %d already exists", key));
  const std::size_t bytes =
      kHeaderBytes + sizeof(hal_stream_data) * static_cast<std::size_t>(depth) *
                         static_cast<std::size_t>(n + 1);
  const int id = rtapi_shmem_new(key, comp, bytes);
  if (id < 0) return report(fail(id, "stream %d: cannot allocate %zu bytes", key, bytes));
  void* mem = nullptr;
  rtapi_shmem_getptr(id, &mem);
  auto* f = new (mem) hal_stream_shm;
  f->num_pins = n;
  f->depth = static_cast<unsigned>(depth);
  std::memcpy(f->type, types, sizeof(hal_type_t) * static_cast<std::size_t>(n));
  f->magic = kStreamMagic;
  stream->comp_id = comp;
  stream->shmem_id = id;
  stream->fifo = f;
  return 0;
}

int hal_stream_attach(hal_stream_t* stream, int comp, int key, const char* typestring) {
  State& s = state();
  Lock lock(s.mu);
  if (stream == nullptr) return report(fail(-EINVAL, "stream %d: no hal_stream_t", key));
  stream->comp_id = stream->shmem_id = -1;
  stream->fifo = nullptr;
  const int existing = block_with_key(key);
  void* mem = nullptr;
  if (existing == 0 || rtapi_shmem_getptr(existing, &mem) < 0 ||
      static_cast<hal_stream_shm*>(mem)->magic != kStreamMagic)
    return report(fail(-EINVAL, "no stream with key %d (create it first)", key));
  auto* f = static_cast<hal_stream_shm*>(mem);
  if (typestring != nullptr) {
    hal_type_t types[HAL_STREAM_MAX_PINS];
    const int n = parse_types(typestring, types);
    if (n < 0) return report(n);
    if (n != f->num_pins)
      return report(fail(-EINVAL, "stream %d has %d elements, '%s' has %d", key, f->num_pins,
                         typestring, n));
    for (int i = 0; i < n; ++i)
      if (types[i] != f->type[i])
        return report(fail(-EINVAL, "stream %d: element %d is %s, '%s' asks for %s", key, i,
                           type_text(f->type[i]), typestring, type_text(types[i])));
  }
  const int id = rtapi_shmem_new(key, comp, kHeaderBytes);  // one more reference
  if (id < 0) return report(fail(id, "stream %d: cannot attach (component %d)", key, comp));
  stream->comp_id = comp;
  stream->shmem_id = id;
  stream->fifo = f;
  return 0;
}

int hal_stream_detach(hal_stream_t* stream) {
  if (stream == nullptr) return 0;
  if (stream->shmem_id > 0) rtapi_shmem_delete(stream->shmem_id, stream->comp_id);
  stream->comp_id = stream->shmem_id = -1;
  stream->fifo = nullptr;
  return 0;
}

void hal_stream_destroy(hal_stream_t* stream) { hal_stream_detach(stream); }

int hal_stream_element_count(hal_stream_t* stream) { return stream->fifo->num_pins; }

hal_type_t hal_stream_element_type(hal_stream_t* stream, int idx) {
  const hal_stream_shm* f = stream->fifo;
  return idx >= 0 && idx < f->num_pins ? f->type[idx] : HAL_TYPE_UNSPECIFIED;
}

int hal_stream_write(hal_stream_t* stream, union hal_stream_data* buf) {
  hal_stream_shm* f = stream->fifo;
  const unsigned in = f->in.load(std::memory_order_relaxed);
  const unsigned next = advance(f, in);
  if (next == f->out.load(std::memory_order_acquire)) {
    f->num_overruns.fetch_add(1, std::memory_order_relaxed);
    return -ENOSPC;
  }
  const auto stride = static_cast<std::size_t>(f->num_pins) + 1;
  hal_stream_data* slot = records(f) + in * stride;
  std::memcpy(slot, buf, sizeof(hal_stream_data) * static_cast<std::size_t>(f->num_pins));
  slot[f->num_pins].u = ++f->this_sample;
  f->in.store(next, std::memory_order_release);
  return 0;
}

int hal_stream_read(hal_stream_t* stream, union hal_stream_data* buf, unsigned* sampleno) {
  hal_stream_shm* f = stream->fifo;
  const unsigned out = f->out.load(std::memory_order_relaxed);
  if (out == f->in.load(std::memory_order_acquire)) {
    f->num_underruns.fetch_add(1, std::memory_order_relaxed);
    return -ENOSPC;
  }
  const auto stride = static_cast<std::size_t>(f->num_pins) + 1;
  const hal_stream_data* slot = records(f) + out * stride;
  std::memcpy(buf, slot, sizeof(hal_stream_data) * static_cast<std::size_t>(f->num_pins));
  if (sampleno != nullptr) *sampleno = slot[f->num_pins].u;
  f->out.store(advance(f, out), std::memory_order_release);
  return 0;
}

bool hal_stream_readable(hal_stream_t* stream) {
  const hal_stream_shm* f = stream->fifo;
  return f->in.load(std::memory_order_acquire) != f->out.load(std::memory_order_relaxed);
}

bool hal_stream_writable(hal_stream_t* stream) {
  const hal_stream_shm* f = stream->fifo;
  return advance(f, f->in.load(std::memory_order_relaxed)) !=
         f->out.load(std::memory_order_acquire);
}

int hal_stream_depth(hal_stream_t* stream) {
  const hal_stream_shm* f = stream->fifo;
  const unsigned in = f->in.load(std::memory_order_acquire);
  const unsigned out = f->out.load(std::memory_order_acquire);
  return static_cast<int>((in + f->depth - out) % f->depth);
}

int hal_stream_maxdepth(hal_stream_t* stream) { return static_cast<int>(stream->fifo->depth); }

int hal_stream_num_underruns(hal_stream_t* stream) {
  return static_cast<int>(stream->fifo->num_underruns.load(std::memory_order_relaxed));
}

int hal_stream_num_overruns(hal_stream_t* stream) {
  return static_cast<int>(stream->fifo->num_overruns.load(std::memory_order_relaxed));
}

// ULAPI-only in hal.h; the shim is one library for both sides, so they are defined here too.
void hal_stream_wait_readable(hal_stream_t* stream, sig_atomic_t* stop);
void hal_stream_wait_writable(hal_stream_t* stream, sig_atomic_t* stop);

void hal_stream_wait_readable(hal_stream_t* stream, sig_atomic_t* stop) {
  while (!hal_stream_readable(stream) && (stop == nullptr || *stop == 0)) rtapi_delay(10000000);
}

void hal_stream_wait_writable(hal_stream_t* stream, sig_atomic_t* stop) {
  while (!hal_stream_writable(stream) && (stop == nullptr || *stop == 0)) rtapi_delay(10000000);
}

}  // extern "C"
