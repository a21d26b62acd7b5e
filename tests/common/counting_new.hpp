// A counting global operator new on top of malloc (counting_new.cpp), for the tests that check
// that frames allocate nothing: an executable that lists counting_new.cpp among its sources has
// it in place of the standard one. Counting is global and atomic, so a worker thread's
// allocations count too.
#pragma once

#include <atomic>

namespace noneuclid::test {

extern std::atomic<bool> g_counting;    // count while true
extern std::atomic<long> g_allocations;  // allocations counted

// Counting on, from zero.
inline void start_counting() {
    g_allocations = 0;
    g_counting = true;
}
// Counting off: the allocations since start_counting.
inline long stop_counting() {
    g_counting = false;
    return g_allocations.load();
}

}  // namespace noneuclid::test
