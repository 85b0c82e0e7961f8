// The firtp_tp module's operator new and delete: memory comes from one arena reserved and touched
// when the module loads, never from malloc in the servo thread.
//
// Why: LinuxCNC sends the axis limits after the planner was created, so TpCore builds its
// Planner (std::vector inside) from them in the servo thread, once, before the
// first move (and again only if limits, period or MAX_FEED_OVERRIDE change while idle). With
// this arena that build takes blocks reserved at load: freed blocks are kept per size and a
// rebuild of the same sizes gets the same blocks back; other sizes come from the unused rest
// (bump). Nothing is returned to the system. Only this module sees these operators: it is
// linked -Bsymbolic and exports nothing but its tp* functions and rtapi_* entries, so other
// modules and rtapi_app keep the C++ library's operators.
//
// Not thread-safe by design: the module allocates in rtapi_app_main, in rtapi_app_exit and in
// the servo thread (motmod calls every tp* function from it), never two at once. Out of arena
// (or before tp_arena_reserve), allocation falls back to malloc with a message.
#include "tp_arena.hpp"

#include "rtapi.h"

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

namespace {

constexpr std::size_t header = 64;  // in front of every block: size and alignment (keeps 64-byte alignment)
constexpr int size_classes = 64;

struct Header {
    std::size_t size;
    std::size_t align;
};

struct FreeBlock {
    FreeBlock* next;
};

struct SizeClass {
    std::size_t size = 0;
    std::size_t align = 0;
    FreeBlock* blocks = nullptr;
};

unsigned char* arena = nullptr;
std::size_t arena_size = 0;
std::size_t arena_used = 0;
SizeClass classes[size_classes];
bool warned = false;

bool in_arena(const void* p) {
    const auto* q = static_cast<const unsigned char*>(p);
    return arena != nullptr && q >= arena && q < arena + arena_size;
}

void* fallback(std::size_t size, std::size_t align) {
    if (!warned) {
        rtapi_print_msg(RTAPI_MSG_ERR, "firtp_tp: memory arena %s: allocating with malloc (raise arena_mb)\n",
                        arena == nullptr ? "not reserved yet" : "exhausted");
        warned = true;
    }
    void* p = nullptr;
    if (posix_memalign(&p, align < sizeof(void*) ? sizeof(void*) : align, size == 0 ? 1 : size) != 0) return nullptr;
    return p;
}

void* allocate(std::size_t size, std::size_t align) {
    if (align < 16) align = 16;
    if (size == 0) size = 1;
    if (arena == nullptr || align > header) return fallback(size, align);
    for (SizeClass& c : classes)
        if (c.size == size && c.align == align && c.blocks != nullptr) {
            FreeBlock* b = c.blocks;
            c.blocks = b->next;
            return b;
        }
    // Bump: header, then the block at a multiple of 64 (arena and header are 64-aligned).
    const std::size_t rounded = (size + header - 1) / header * header;
    if (arena_used + header + rounded > arena_size) return fallback(size, align);
    unsigned char* block = arena + arena_used + header;
    auto* h = reinterpret_cast<Header*>(block - header);
    h->size = size;
    h->align = align;
    arena_used += header + rounded;
    return block;
}

void release(void* p) {
    if (p == nullptr) return;
    if (!in_arena(p)) {
        std::free(p);
        return;
    }
    const auto* h = reinterpret_cast<const Header*>(static_cast<unsigned char*>(p) - header);
    SizeClass* spare = nullptr;
    for (SizeClass& c : classes) {
        if (c.size == h->size && c.align == h->align) {
            spare = &c;
            break;
        }
        if (spare == nullptr && c.size == 0) spare = &c;
    }
    if (spare == nullptr) return;  // every class taken by other sizes: the block stays unused
    spare->size = h->size;
    spare->align = h->align;
    auto* b = static_cast<FreeBlock*>(p);
    b->next = spare->blocks;
    spare->blocks = b;
}

}  // namespace

bool tp_arena_reserve(std::size_t bytes) {
    if (arena != nullptr) return true;
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) return false;
    std::memset(p, 0, bytes);  // touch every page now, not in the servo thread
    arena = static_cast<unsigned char*>(p);
    arena_size = bytes;
    return true;
}

std::size_t tp_arena_used() { return arena_used; }

void* operator new(std::size_t size) {
    if (void* p = allocate(size, 16)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    if (void* p = allocate(size, 16)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, std::align_val_t align) {
    if (void* p = allocate(size, static_cast<std::size_t>(align))) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t align) {
    if (void* p = allocate(size, static_cast<std::size_t>(align))) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size, 16); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate(size, 16); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
