// What runs before main on a Cortex-M3: the vector table (the stack's top and the reset handler
// first), the reset handler (initialised data copied from flash, .bss zeroed, static
// constructors, main), and the heap newlib's malloc grows into (_sbrk), between .bss and the
// stack (mps2-an385.ld). Every allocation is counted (heap.hpp): the firmware allocates only
// while it starts, and checks that its frames allocate nothing.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

#include "heap.hpp"

extern "C" {
extern uint32_t mcu_data_load, mcu_data_start, mcu_data_end, mcu_bss_start, mcu_bss_end;
extern uint8_t mcu_heap_start, mcu_heap_end, mcu_stack_top;
int main();
void __libc_init_array();
[[noreturn]] void mcu_reset();
[[noreturn]] void mcu_fault();
}

namespace {
std::size_t g_allocations = 0;
uint8_t* g_break = &mcu_heap_start;
}  // namespace

namespace noneuclid::mcu {
std::size_t heap_allocations() { return g_allocations; }
std::size_t heap_used() { return static_cast<std::size_t>(g_break - &mcu_heap_start); }
std::size_t heap_room() { return static_cast<std::size_t>(&mcu_heap_end - &mcu_heap_start); }
}  // namespace noneuclid::mcu

extern "C" void mcu_reset() {
    for (uint32_t *from = &mcu_data_load, *to = &mcu_data_start; to < &mcu_data_end;) *to++ = *from++;
    for (uint32_t* p = &mcu_bss_start; p < &mcu_bss_end;) *p++ = 0;
    __libc_init_array();
    main();
    for (;;) {
    }
}

// A fault (a bad address, an undefined instruction): stops here, where a debugger finds it.
extern "C" void mcu_fault() {
    for (;;) {
    }
}

// newlib's own allocations (its C library: dtoa's number cache, say) go through _malloc_r, not
// operator new: linked with --wrap=_malloc_r, they come here and are counted too.
extern "C" void* __real__malloc_r(struct _reent* r, std::size_t bytes);
extern "C" void* __wrap__malloc_r(struct _reent* r, std::size_t bytes) {
    ++g_allocations;
    return __real__malloc_r(r, bytes);
}

// newlib's malloc asks for memory here: the room between .bss and the stack, never given back.
extern "C" void* _sbrk(ptrdiff_t grow) {
    if (grow < 0 || grow > &mcu_heap_end - g_break) return reinterpret_cast<void*>(-1);
    uint8_t* const was = g_break;
    g_break += grow;
    return was;
}

// The vector table: the initial stack pointer, reset, NMI, and the faults (HardFault,
// MemManage, BusFault, UsageFault). Nothing here uses an interrupt.
using Handler = void (*)();
extern "C" __attribute__((section(".vectors"), used)) const Handler mcu_vectors[] = {
    reinterpret_cast<Handler>(&mcu_stack_top), mcu_reset, mcu_fault, mcu_fault, mcu_fault, mcu_fault, mcu_fault,
};

// (Counted by malloc, above.) -fno-exceptions: a failed allocation ends the program.
void* operator new(std::size_t bytes) {
    if (void* p = std::malloc(bytes ? bytes : 1)) return p;
    std::abort();
}
void* operator new[](std::size_t bytes) { return operator new(bytes); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

// newlib's exit and abort (a failed allocation) end here: under a debugger or qemu, said and
// ended through semihosting (a real board stops in mcu_fault's loop).
extern "C" [[noreturn]] void mcu_stopped(int status);
extern "C" [[noreturn]] void _exit(int status) { mcu_stopped(status); }
