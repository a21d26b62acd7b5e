// libFuzzer's entry point for one harness (NONEUCLID_FUZZ_HARNESS, set by CMakeLists.txt).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    NONEUCLID_FUZZ_HARNESS(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
