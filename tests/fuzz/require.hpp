// A property a fuzz target checks: abort (libFuzzer then saves the input) naming it.
#pragma once

#include <cstdio>
#include <cstdlib>

#define require(condition)                                                                  \
    do {                                                                                  \
        if (!(condition)) {                                                               \
            std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #condition); \
            std::abort();                                                                 \
        }                                                                                 \
    } while (false)
