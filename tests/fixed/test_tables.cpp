// The compile-time tables against std:: (which also checks constexpr_math.hpp), and their size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fixed/math.hpp"
#include "geometry/fx/equidistant.hpp"
#include "fixed/tables.hpp"
#include "test_common.hpp"

namespace t = noneuclid::fx::tables;

namespace {

using noneuclid::test::kPi;

// r / S_K(r) as a function of w = C_K(r), from std:: alone.
double equidistant_ratio(double w) {
    if (w == 1) return 1;
    return w < 1 ? std::acos(w) / std::sqrt(1 - w * w) : std::acosh(w) / std::sqrt(w * w - 1);
}

template <class Table, class F>
void expect_table(const Table& table, double scale, std::size_t used, F f, const char* name) {
    for (std::size_t i = 0; i < used; ++i)
        ASSERT_NEAR(static_cast<double>(table[i]) / scale, f(static_cast<double>(i)), 0.5 / scale + 1e-13)
            << name << "[" << i << "]";
}

TEST(Tables, EntriesMatchStdToHalfAStep) {
    expect_table(t::sin_q30, 0x1p30, 2049, [](double i) { return std::sin(2 * kPi * i / 2048); }, "sin");
    expect_table(t::atan_units, 4294967296.0 / (2 * kPi), 513,
                 [](double i) { return std::atan(i / 512); }, "atan");
    expect_table(t::asin_q30, 0x1p30, 257, [](double i) { return std::asin(i / 512); }, "asin");
    expect_table(t::sqrt_q31, 0x1p31, 193, [](double i) { return std::sqrt((64 + i) / 256); }, "sqrt");
    expect_table(t::recip_q31, 0x1p31, 257, [](double i) { return 1 / (1 + i / 256); }, "recip");
    expect_table(t::exp2_q30, 0x1p30, 256, [](double j) { return std::exp2(j / 256); }, "exp2");
    expect_table(t::log2_q31, 0x1p31, 513, [](double i) { return std::log2(1 + i / 512); }, "log2");
    expect_table(t::sf_q28, 0x1p28, 1281, [](double i) {
        const double u = -10 + i / 64, s = std::sqrt(std::fabs(u));
        return u == 0 ? 1.0 : (u > 0 ? std::sin(s) / s : std::sinh(s) / s);
    }, "Sf");
    expect_table(t::cf_q27, 0x1p27, 2561, [](double i) {
        const double u = -10 + i / 128, s = std::sqrt(std::fabs(u));
        return u >= 0 ? std::cos(s) : std::cosh(s);
    }, "Cf");
    expect_table(t::asf_q30, 0x1p30, 1153, [](double i) {
        const double u = -4 + i / 256, s = std::sqrt(std::fabs(u));
        return u == 0 ? 1.0 : (u > 0 ? std::asin(s) / s : std::asinh(s) / s);
    }, "ASf");
    expect_table(t::atf_q30, 0x1p30, 769, [](double i) {
        const double u = -0.5 + i / 512, s = std::sqrt(std::fabs(u));
        return u == 0 ? 1.0 : (u > 0 ? std::atan(s) / s : std::atanh(s) / s);
    }, "ATf");
    expect_table(t::atf_low_q29, 0x1p29, 1793, [](double i) {
        const double u = -15.0 / 16 + i / 4096, s = std::sqrt(-u);
        return std::atanh(s) / s;
    }, "ATf low");
    expect_table(t::equi_q30, 0x1p30, 4097, [](double i) { return equidistant_ratio(i / 128); }, "E");
    expect_table(t::equi_south_q29, 0x1p29, 257, [](double i) { return equidistant_ratio(-0.5 + i / 512); }, "E south");
}

// E(w) = r / S_K(r) for w = C_K(r), through every Q16.16 value of w in [-1/2, 32): the tables'
// linear interpolation against std::acos / std::acosh. Worst measured: 7.57e-6 (at w = 1/256,
// just inside the sphere's equator, where E curves most on [0, 32)), 2.03e-6 from w = 1 on (the
// hyperbolic plane); past the equator (its own table, 4 times finer) see the test's recorded
// properties (--gtest_output=xml).
TEST(Tables, EquidistantRatioInterpolatesToTheStatedError) {
    double worst = 0, worst_hyperbolic = 0;
    for (uint32_t w = 0; w < (32u << 16); ++w) {
        const double x = w / 65536.0, ref = equidistant_ratio(x);
        const double e = std::fabs(noneuclid::fx::equidistant_ratio_q30(w) / 0x1p30 - ref) / ref;
        worst = std::max(worst, e);
        if (x >= 1) worst_hyperbolic = std::max(worst_hyperbolic, e);
    }
    double worst_south = 0;  // past the sphere's equator, w in [-1/2, 0)
    for (int32_t w = -(1 << 15); w < 0; ++w) {
        const double ref = equidistant_ratio(w / 65536.0);
        worst_south = std::max(worst_south, std::fabs(noneuclid::fx::equidistant_ratio_south_q29(w) / 0x1p29 - ref) / ref);
    }
    auto record = [](const char* key, double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3g", v);
        RecordProperty(key, text);
    };
    record("worst_relative_error", worst);
    record("worst_relative_error_w_ge_1", worst_hyperbolic);
    record("worst_relative_error_w_lt_0", worst_south);
    EXPECT_LE(worst, 7.6e-6);
    EXPECT_LE(worst_hyperbolic, 2.1e-6);
    EXPECT_LE(worst_south, 2.8e-6);
}

TEST(Tables, FitTheMemoryBudget) {
    EXPECT_LE(t::table_bytes, 64u * 1024u);
    // What docs/accuracy.md and docs/design.md report.
    RecordProperty("table_bytes", static_cast<int>(t::table_bytes));
}

}  // namespace
