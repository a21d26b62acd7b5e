// The counting operator new of counting_new.hpp. It pairs malloc with free on purpose (so it runs
// under ASan too); an executable linking it builds with -Wno-mismatched-new-delete, as GCC's
// check cannot see that they are a matched pair.
#include "counting_new.hpp"

#include <cstdlib>
#include <new>

namespace noneuclid::test {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace noneuclid::test

void* operator new(std::size_t n) {
    if (noneuclid::test::g_counting.load(std::memory_order_relaxed))
        noneuclid::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
