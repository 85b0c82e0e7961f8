// Reading and writing HAL pins that another thread uses at the same time.
//
// A pin is shared memory: firtp.update writes its outputs in the servo thread while a
// non-real-time component (firtp-bridge, halcmd) reads them from another thread, and the other way
// round for inputs. HAL declares pins volatile and relies on aligned word accesses being atomic;
// in C++ a plain concurrent access is still a data race (undefined behaviour, and ThreadSanitizer
// reports it). Relaxed atomic accesses say what HAL means: on x86-64 and ARM64 they are the same
// single load or store (no lock, no fence), with LinuxCNC's hal.h as with hal-shim's.
#pragma once

#include <type_traits>

namespace firtp::hal_pin {

template <typename T>
inline T get(const volatile T* pin) {
    T value;
    __atomic_load(pin, &value, __ATOMIC_RELAXED);
    return value;
}

template <typename T>
inline void set(volatile T* pin, std::type_identity_t<T> value) {
    __atomic_store(pin, &value, __ATOMIC_RELAXED);
}

}  // namespace firtp::hal_pin
