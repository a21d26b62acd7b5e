// Runs one function N times for instruction counting under qemu (arm-insncount):
//     insn_probe FUNCTION fixed|double|float N
// The cost of a call is (count at N - count at 0) / N: the run at N = 0 does the same set-up
// (input generation, start-up) and no calls. tests/bench/arm-insncount.sh does the arithmetic.
// The loop itself (load input, accumulate, count) is included in every implementation alike;
// `insn_probe nop fixed N` measures it.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "functions.hpp"

namespace nb = noneuclid::bench;

namespace {

nb::Inputs g_in;

template <int I>
double run(const char* impl, long n) {
    constexpr nb::Function fn = nb::kFunctions[I];
    double acc = 0;
    int64_t iacc = 0;
    if (std::strcmp(impl, "fixed") == 0) {
        for (long k = 0; k < n; ++k) iacc += fn.fixed_fn(g_in.fixed_raw[k & 1023], g_in.fixed_raw2[k & 1023]);
    } else if (std::strcmp(impl, "double") == 0) {
        for (long k = 0; k < n; ++k) acc += fn.double_fn(g_in.d[k & 1023], g_in.d2[k & 1023]);
    } else if (std::strcmp(impl, "float") == 0) {
        for (long k = 0; k < n; ++k) acc += static_cast<double>(fn.float_fn(g_in.f[k & 1023], g_in.f2[k & 1023]));
    } else {
        std::fprintf(stderr, "insn_probe: implementation must be fixed, double or float, not '%s'.\n", impl);
        std::exit(2);
    }
    return acc + static_cast<double>(iacc);
}

template <int... I>
bool dispatch(const char* name, const char* impl, long n, double& out, std::integer_sequence<int, I...>) {
    return ((std::strcmp(name, nb::kFunctions[I].name) == 0 ? (nb::make_inputs(nb::kFunctions[I], g_in),
                                                                 out = run<I>(impl, n), true)
                                                              : false) || ...);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: insn_probe FUNCTION fixed|double|float N\n");
        return 2;
    }
    const long n = std::atol(argv[3]);
    double out = 0;
    if (std::strcmp(argv[1], "nop") == 0) {
        nb::make_inputs(nb::kFunctions[0], g_in);
        int64_t acc = 0;
        for (long k = 0; k < n; ++k) acc += g_in.fixed_raw[k & 1023];
        out = static_cast<double>(acc);
    } else if (!dispatch(argv[1], argv[2], n, out, std::make_integer_sequence<int, nb::kFunctionCount>{})) {
        std::fprintf(stderr, "insn_probe: unknown function '%s'.\n", argv[1]);
        return 2;
    }
    std::printf("%s %s %ld checksum %.17g\n", argv[1], argv[2], n, out);
    return 0;
}
