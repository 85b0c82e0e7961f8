// The hooks behind rt_probe.hpp. This file must be linked into the test executable itself (not a
// shared library): definitions in the executable come first in symbol lookup, so they replace
// glibc's for every library of the process.
#include "rt_probe.hpp"

#include <dlfcn.h>
#include <pthread.h>
#include <semaphore.h>
#include <time.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define FIRTP_PROBE_SANITIZER_MALLOC 1
#endif
#if __has_feature(thread_sanitizer)
#define FIRTP_PROBE_TSAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define FIRTP_PROBE_SANITIZER_MALLOC 1
#endif
#if defined(__SANITIZE_THREAD__)
#define FIRTP_PROBE_TSAN 1
#endif

#ifdef FIRTP_PROBE_SANITIZER_MALLOC
#include <sanitizer/allocator_interface.h>
#endif

namespace {

// Static TLS of the executable: reading it never allocates.
__attribute__((tls_model("initial-exec"))) thread_local bool t_armed = false;
__attribute__((tls_model("initial-exec"))) thread_local long t_allocations = 0;
__attribute__((tls_model("initial-exec"))) thread_local long t_frees = 0;
__attribute__((tls_model("initial-exec"))) thread_local long t_locks = 0;

inline void count_allocation() {
    if (t_armed) ++t_allocations;
}
inline void count_free(const void* p) {
    if (t_armed && p != nullptr) ++t_frees;
}
[[maybe_unused]] inline void count_lock() {  // unused under TSan
    if (t_armed) ++t_locks;
}

}  // namespace

namespace firtp::rt_probe {

void arm() {
    t_allocations = 0;
    t_frees = 0;
    t_locks = 0;
    t_armed = true;
}

Counts current() { return {t_allocations, t_frees, t_locks}; }

Counts disarm() {
    t_armed = false;
    return current();
}

bool allocations_counted() { return true; }

bool locks_counted() {
#ifdef FIRTP_PROBE_TSAN
    return false;
#else
    return true;
#endif
}

}  // namespace firtp::rt_probe

// ---- allocations ------------------------------------------------------------------------------

#ifdef FIRTP_PROBE_SANITIZER_MALLOC

namespace {
void on_malloc(const volatile void*, std::size_t) { count_allocation(); }
void on_free(const volatile void* p) { count_free(const_cast<const void*>(p)); }
[[maybe_unused]] const int installed = __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free);
}  // namespace

#else

extern "C" {
// glibc's allocator under its internal names (exported since glibc 2.0).
void* __libc_malloc(std::size_t) noexcept;
void* __libc_calloc(std::size_t, std::size_t) noexcept;
void* __libc_realloc(void*, std::size_t) noexcept;
void __libc_free(void*) noexcept;
void* __libc_memalign(std::size_t, std::size_t) noexcept;
void* __libc_valloc(std::size_t) noexcept;
void* __libc_pvalloc(std::size_t) noexcept;

void* malloc(std::size_t n) noexcept {
    count_allocation();
    return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t size) noexcept {
    count_allocation();
    return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t n) noexcept {
    count_allocation();
    return __libc_realloc(p, n);
}
void free(void* p) noexcept {
    count_free(p);
    __libc_free(p);
}
void* memalign(std::size_t alignment, std::size_t n) noexcept {
    count_allocation();
    return __libc_memalign(alignment, n);
}
void* aligned_alloc(std::size_t alignment, std::size_t n) noexcept {
    count_allocation();
    return __libc_memalign(alignment, n);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t n) noexcept {
    if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
    count_allocation();
    void* p = __libc_memalign(alignment, n);
    if (p == nullptr && n != 0) return ENOMEM;
    *out = p;
    return 0;
}
void* valloc(std::size_t n) noexcept {
    count_allocation();
    return __libc_valloc(n);
}
void* pvalloc(std::size_t n) noexcept {
    count_allocation();
    return __libc_pvalloc(n);
}
}  // extern "C"

#endif

// ---- locks ------------------------------------------------------------------------------------

#ifndef FIRTP_PROBE_TSAN

namespace {
// The next definition of `name` after this executable's (glibc's). dlsym takes no pthread lock.
template <typename F>
F next(F& cache, const char* name) {
    F f = __atomic_load_n(&cache, __ATOMIC_ACQUIRE);
    if (f == nullptr) {
        f = reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
        __atomic_store_n(&cache, f, __ATOMIC_RELEASE);
    }
    return f;
}
}  // namespace

// `spec`: glibc declares the pthread functions nothrow (noexcept in C++), the sem_* ones not.
#define FIRTP_PROBE_FORWARD(ret, name, params, args, spec)       \
    ret name params spec {                                      \
        count_lock();                                           \
        static ret(*real) params = nullptr;                     \
        return next(real, #name) args;                          \
    }

extern "C" {
FIRTP_PROBE_FORWARD(int, pthread_mutex_lock, (pthread_mutex_t * m), (m), noexcept)
FIRTP_PROBE_FORWARD(int, pthread_mutex_trylock, (pthread_mutex_t * m), (m), noexcept)
FIRTP_PROBE_FORWARD(int, pthread_mutex_timedlock, (pthread_mutex_t * m, const struct timespec* t), (m, t), noexcept)
FIRTP_PROBE_FORWARD(int, pthread_mutex_clocklock, (pthread_mutex_t * m, clockid_t c, const struct timespec* t),
                    (m, c, t), noexcept)
FIRTP_PROBE_FORWARD(int, pthread_rwlock_rdlock, (pthread_rwlock_t * l), (l), noexcept)
FIRTP_PROBE_FORWARD(int, pthread_rwlock_wrlock, (pthread_rwlock_t * l), (l), noexcept)
FIRTP_PROBE_FORWARD(int, pthread_rwlock_tryrdlock, (pthread_rwlock_t * l), (l), noexcept)
FIRTP_PROBE_FORWARD(int, pthread_rwlock_trywrlock, (pthread_rwlock_t * l), (l), noexcept)
FIRTP_PROBE_FORWARD(int, pthread_spin_lock, (pthread_spinlock_t * l), (l), noexcept)
FIRTP_PROBE_FORWARD(int, pthread_spin_trylock, (pthread_spinlock_t * l), (l), noexcept)
FIRTP_PROBE_FORWARD(int, sem_wait, (sem_t * s), (s), )
FIRTP_PROBE_FORWARD(int, sem_trywait, (sem_t * s), (s), )
FIRTP_PROBE_FORWARD(int, sem_timedwait, (sem_t * s, const struct timespec* t), (s, t), )
}  // extern "C"

#endif
