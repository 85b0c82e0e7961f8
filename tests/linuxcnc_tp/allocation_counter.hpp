// Counts calls of the global operator new in this test program (allocation_counter.cpp replaces it),
// to show that code that must not allocate does not.
#pragma once

namespace firtp::test {
long allocation_count();
}
