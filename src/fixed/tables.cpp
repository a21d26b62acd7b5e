// The lookup tables, computed by the compiler. `constexpr` on each definition forces the
// computation to happen at compile time; `const` places the result in .rodata.
#include "fixed/tables.hpp"

#include "fixed/constexpr_math.hpp"
#include "fixed/division.hpp"

namespace noneuclid::fx::tables {
namespace {

template <class T, std::size_t N, class F>
constexpr std::array<T, N> build(F f) {
    std::array<T, N> t{};
    for (std::size_t i = 0; i < N; ++i) t[i] = static_cast<T>(cx::round_to_ll(f(static_cast<int>(i))));
    return t;
}

constexpr double q30 = 1073741824.0;  // 2^30
constexpr double q31 = 2147483648.0;  // 2^31

}  // namespace

constexpr std::array<int32_t, (1 << kSinBits) + 2> sin_q30 =
    build<int32_t, (1 << kSinBits) + 2>([](int i) {
        return cx::sin(2 * cx::pi * i / (1 << kSinBits)) * q30;
    });

constexpr std::array<uint32_t, (1 << kAtanBits) + 2> atan_units =
    build<uint32_t, (1 << kAtanBits) + 2>([](int i) {
        const int n = i > (1 << kAtanBits) ? (1 << kAtanBits) : i;  // pad repeats the end
        return cx::atan(static_cast<double>(n) / (1 << kAtanBits)) * (4294967296.0 / (2 * cx::pi));
    });

constexpr std::array<int32_t, (1 << (kAsinBits - 1)) + 2> asin_q30 =
    build<int32_t, (1 << (kAsinBits - 1)) + 2>([](int i) {
        const double x = static_cast<double>(i) / (1 << kAsinBits);
        return cx::asin(x > 0.5 ? 0.5 : x) * q30;
    });

constexpr std::array<uint32_t, 192 + 2> sqrt_q31 = build<uint32_t, 192 + 2>([](int i) {
    const double m = (64.0 + (i > 192 ? 192 : i)) / 256.0;
    return cx::sqrt(m) * q31;
});

constexpr std::array<uint32_t, 256 + 2> recip_q31 = build<uint32_t, 256 + 2>([](int i) {
    return q31 / (1.0 + (i > 256 ? 256 : i) / 256.0);
});

constexpr std::array<uint32_t, 256> exp2_q30 = build<uint32_t, 256>([](int j) {
    return cx::exp(cx::ln2 * j / 256.0) * q30;
});

constexpr std::array<uint32_t, (1 << kLog2Bits) + 2> log2_q31 =
    build<uint32_t, (1 << kLog2Bits) + 2>([](int i) {
        const int n = i > (1 << kLog2Bits) ? (1 << kLog2Bits) : i;
        return cx::log2(1.0 + static_cast<double>(n) / (1 << kLog2Bits)) * q31;
    });

constexpr std::array<int32_t, (kSfCfRange * 2 << kSfStepBits) + 2> sf_q28 =
    build<int32_t, (kSfCfRange * 2 << kSfStepBits) + 2>([](int i) {
        return cx::Sf(-kSfCfRange + static_cast<double>(i) / (1 << kSfStepBits)) * (1 << 28);
    });

constexpr std::array<int32_t, (kSfCfRange * 2 << kCfStepBits) + 2> cf_q27 =
    build<int32_t, (kSfCfRange * 2 << kCfStepBits) + 2>([](int i) {
        return cx::Cf(-kSfCfRange + static_cast<double>(i) / (1 << kCfStepBits)) * (1 << 27);
    });

constexpr std::array<int32_t, ((kASfLow << kASfStepBits) + (1 << (kASfStepBits - 1))) + 2>
    asf_q30 = build<int32_t, ((kASfLow << kASfStepBits) + (1 << (kASfStepBits - 1))) + 2>(
        [](int i) { return cx::ASf(-kASfLow + static_cast<double>(i) / (1 << kASfStepBits)) * q30; });

constexpr std::array<int32_t, (3 << (kATfStepBits - 1)) + 2> atf_q30 =
    build<int32_t, (3 << (kATfStepBits - 1)) + 2>([](int i) {
        return cx::ATf(-0.5 + static_cast<double>(i) / (1 << kATfStepBits)) * q30;
    });

constexpr std::array<int32_t, (7 << (kATfLowStepBits - 4)) + 2> atf_low_q29 =
    build<int32_t, (7 << (kATfLowStepBits - 4)) + 2>([](int i) {
        return cx::ATf(-15.0 / 16 + static_cast<double>(i) / (1 << kATfLowStepBits)) * (q30 / 2);
    });

namespace {
constexpr double equi(double w) { return 2 * cx::ATf((1 - w) / (1 + w)) / (1 + w); }
}  // namespace

constexpr std::array<int32_t, (kEquiRange << kEquiStepBits) + 2> equi_q30 =
    build<int32_t, (kEquiRange << kEquiStepBits) + 2>([](int i) {
        return equi(static_cast<double>(i) / (1 << kEquiStepBits)) * q30;
    });

constexpr std::array<int32_t, (1 << (kEquiSouthStepBits - 1)) + 2> equi_south_q29 =
    build<int32_t, (1 << (kEquiSouthStepBits - 1)) + 2>([](int i) {
        return equi(-0.5 + static_cast<double>(i) / (1 << kEquiSouthStepBits)) * (q30 / 2);
    });

}  // namespace noneuclid::fx::tables

namespace noneuclid::fx::detail {
int64_t div_round_portable(int64_t n, uint32_t d) noexcept { return div_round<false>(n, d); }
}  // namespace noneuclid::fx::detail
