// ARM semihosting calls (semihosting.hpp): operation number in r0, a pointer to its arguments
// in r1, `bkpt 0xAB`, the result in r0.
#include "semihosting.hpp"

#include <cstring>

namespace noneuclid::mcu::semihosting {
namespace {

enum Op : uint32_t {
    sys_open = 0x01, sys_close = 0x02, sys_write0 = 0x04, sys_write = 0x05, sys_read = 0x06,
    sys_flen = 0x0C, sys_get_cmdline = 0x15, sys_exit = 0x18,
};

uint32_t call(uint32_t op, const void* args) {
    register uint32_t r0 asm("r0") = op;
    register const void* r1 asm("r1") = args;
    asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

}  // namespace

int open(const char* path, const char* mode) {
    // The modes of fopen, by their index in the protocol's table.
    const uint32_t m = std::strcmp(mode, "rb") == 0 ? 1 : std::strcmp(mode, "wb") == 0 ? 5 : 0;
    const uint32_t args[3] = {reinterpret_cast<uint32_t>(path), m, static_cast<uint32_t>(std::strlen(path))};
    return static_cast<int>(call(sys_open, args));
}

bool write(int handle, const void* data, std::size_t bytes) {
    const uint32_t args[3] = {static_cast<uint32_t>(handle), reinterpret_cast<uint32_t>(data), bytes};
    return call(sys_write, args) == 0;  // (the bytes not written)
}

std::size_t read(int handle, void* data, std::size_t bytes) {
    const uint32_t args[3] = {static_cast<uint32_t>(handle), reinterpret_cast<uint32_t>(data), bytes};
    const uint32_t left = call(sys_read, args);  // (the bytes not read)
    return left > bytes ? 0 : bytes - left;
}

void close(int handle) {
    const uint32_t args[1] = {static_cast<uint32_t>(handle)};
    call(sys_close, args);
}

long length(int handle) {
    const uint32_t args[1] = {static_cast<uint32_t>(handle)};
    return static_cast<long>(static_cast<int32_t>(call(sys_flen, args)));
}

void print(const char* text) { call(sys_write0, text); }

bool command_line(char* out, std::size_t size) {
    uint32_t args[2] = {reinterpret_cast<uint32_t>(out), size};
    return call(sys_get_cmdline, args) == 0;
}

void exit(bool success) {
    // On AArch32 the reason is the argument itself: ADP_Stopped_ApplicationExit (qemu exits 0)
    // or ADP_Stopped_RunTimeErrorUnknown (qemu exits 1).
    call(sys_exit, reinterpret_cast<const void*>(success ? 0x20026u : 0x20023u));
    for (;;) {
    }
}

}  // namespace noneuclid::mcu::semihosting
