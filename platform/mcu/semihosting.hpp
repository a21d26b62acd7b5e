// ARM semihosting (the debugger's, or qemu's with -semihosting-config): the firmware's way to the
// host under emulation. Files opened on the host stand in for the display (frames written) and
// the buttons (a recording read); the command line is qemu's `arg=` words; exit ends qemu with a
// status. Each call is one `bkpt 0xAB` trap: on a real board without a debugger attached it
// would stop the core, so only the qemu board (board_qemu.cpp) uses it.
#pragma once

#include <cstddef>
#include <cstdint>

namespace noneuclid::mcu::semihosting {

// A host file, binary, for reading ("rb") or writing ("wb"); -1 if it cannot be opened.
int open(const char* path, const char* mode);
// Whole buffers: true if all bytes went (write) or came (read; false at the end of the file).
bool write(int handle, const void* data, std::size_t bytes);
// Up to `bytes` bytes; how many came (0 at the end or on an error).
std::size_t read(int handle, void* data, std::size_t bytes);
void close(int handle);
// The file's length in bytes, or -1.
long length(int handle);
// A line on the host's stderr (qemu's).
void print(const char* text);
// The command line qemu was given (`-semihosting-config arg=...`), its words parted by spaces.
bool command_line(char* out, std::size_t size);
// Ends the program: qemu exits 0 for success, 1 otherwise.
[[noreturn]] void exit(bool success);

}  // namespace noneuclid::mcu::semihosting
