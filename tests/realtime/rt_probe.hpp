// Counts heap allocations and lock calls made by the calling thread while it is "armed", to show
// that servo-thread code allocates nothing and takes no lock.
//
// How (rt_probe.cpp, linked into the test program only; no LD_PRELOAD):
// - allocations: without a sanitizer this program defines malloc, calloc, realloc, free,
//   memalign, aligned_alloc, posix_memalign, valloc and pvalloc (forwarding to glibc's
//   __libc_* functions), so every allocation of the process goes through them, operator new's
//   included (libstdc++'s calls malloc). Under ASan or TSan, whose runtimes own malloc, the
//   sanitizer's malloc hook (__sanitizer_install_malloc_and_free_hooks) counts the same calls.
// - locks: this program defines pthread_mutex_lock, _trylock, _timedlock, _clocklock,
//   pthread_rwlock_{rd,wr}lock (and try/timed), pthread_spin_lock/trylock, sem_wait/_timedwait/
//   _trywait and pthread_cond_wait/_timedwait, forwarding to the next definition (dlsym
//   RTLD_NEXT). std::mutex and every C library lock reach them. Not under TSan, which intercepts
//   the same functions (locks_counted() is then false).
// Only the armed thread counts: other threads (an LCM or bridge thread) may allocate freely.
#pragma once

namespace firtp::rt_probe {

struct Counts {
    long allocations = 0;  // malloc, calloc, realloc, memalign, ... and so operator new
    long frees = 0;
    long locks = 0;        // lock, trylock, wait calls (0 when !locks_counted())
};

// Starts counting in this thread (counts reset).
void arm();
// Stops counting in this thread and returns what it counted since arm().
Counts disarm();
// What this thread counted so far (armed or not), since the last arm().
Counts current();

bool allocations_counted();  // the hooks are in place (always true on Linux with glibc)
bool locks_counted();        // false under ThreadSanitizer

}  // namespace firtp::rt_probe
