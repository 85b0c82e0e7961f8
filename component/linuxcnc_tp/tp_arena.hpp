// The firtp_tp module's memory arena (tp_arena.cpp replaces operator new and delete in the module).
#pragma once

#include <cstddef>

// Reserves and touches `bytes` at module load (not real-time). False when the system refuses.
bool tp_arena_reserve(std::size_t bytes);
// Bytes handed out from the arena so far (blocks reused from freed ones are not counted again).
std::size_t tp_arena_used();
