// The firmware's heap (startup.cpp): how many allocations so far, the bytes taken from RAM for
// it, and the room it has (RAM less data, .bss and the stack).
#pragma once

#include <cstddef>

namespace noneuclid::mcu {
std::size_t heap_allocations();
std::size_t heap_used();
std::size_t heap_room();
}  // namespace noneuclid::mcu
