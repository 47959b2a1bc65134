#pragma once

// Counting heap allocations, for the tests of "no per-field heap allocation on the hot path"
// (issue 2). Every heap allocation of the process (operator new, and Qt's containers, which call
// malloc directly) goes through malloc, calloc, realloc or the aligned allocators, so this header
// replaces those with counting versions that forward to glibc's own. It defines them: include it
// in one source file of a test executable only.
//
// Under a sanitizer the allocator belongs to the sanitizer and cannot be replaced, and without
// glibc there is nothing to forward to: allocationcounter::available is false there and a test
// should skip.

#include <atomic>
#include <cstddef>

#if defined(__SANITIZE_ADDRESS__)
#define MBSCOPE_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define MBSCOPE_COUNT_ALLOCATIONS 0
#endif
#endif
#if !defined(MBSCOPE_COUNT_ALLOCATIONS) && defined(__GLIBC__)
#define MBSCOPE_COUNT_ALLOCATIONS 1
#endif
#ifndef MBSCOPE_COUNT_ALLOCATIONS
#define MBSCOPE_COUNT_ALLOCATIONS 0
#endif

namespace allocationcounter {

constexpr bool available = MBSCOPE_COUNT_ALLOCATIONS;

inline std::atomic<bool> counting{false};
inline std::atomic<long> allocations{0};

inline void counted()
{
    if (counting.load(std::memory_order_relaxed))
        allocations.fetch_add(1, std::memory_order_relaxed);
}

// Counts from zero until stop().
inline void start()
{
    allocations = 0;
    counting = true;
}

// The allocations made since start().
inline long stop()
{
    counting = false;
    return allocations.load();
}

} // namespace allocationcounter

#if MBSCOPE_COUNT_ALLOCATIONS
// noexcept as glibc declares them (throw()), so that its headers may come before or after.
extern "C" {
void *__libc_malloc(std::size_t size);
void *__libc_calloc(std::size_t count, std::size_t size);
void *__libc_realloc(void *pointer, std::size_t size);
void *__libc_memalign(std::size_t alignment, std::size_t size);

void *malloc(std::size_t size) noexcept
{
    allocationcounter::counted();
    return __libc_malloc(size);
}
void *calloc(std::size_t count, std::size_t size) noexcept
{
    allocationcounter::counted();
    return __libc_calloc(count, size);
}
void *realloc(void *pointer, std::size_t size) noexcept
{
    allocationcounter::counted();
    return __libc_realloc(pointer, size);
}
void *memalign(std::size_t alignment, std::size_t size) noexcept
{
    allocationcounter::counted();
    return __libc_memalign(alignment, size);
}
void *aligned_alloc(std::size_t alignment, std::size_t size) noexcept
{
    allocationcounter::counted();
    return __libc_memalign(alignment, size);
}
int posix_memalign(void **pointer, std::size_t alignment, std::size_t size) noexcept
{
    allocationcounter::counted();
    *pointer = __libc_memalign(alignment, size);
    return *pointer ? 0 : 12; // ENOMEM
}
} // extern "C"
#endif
