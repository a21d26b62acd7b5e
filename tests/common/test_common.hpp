// What many tests share: pi, the fixed-point step, degrees, angles compared on the circle, the
// flat picture's distance of two polar points, a polar point of any engine in double, and a
// directory of a test's own.
// Every GoogleTest executable has tests/common on its include path (noneuclid_gtest).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <system_error>

namespace noneuclid::test {

inline constexpr double kPi = std::numbers::pi;

// One step of fx::fixed (Q16.16), and half of it: the error of a correctly rounded result.
inline constexpr double kStep = 1.0 / 65536;
inline constexpr double kHalfStep = kStep / 2;

// Under qemu-user (a cross tree's tests, built with NONEUCLID_EMULATED) every instruction is
// emulated, floating point ten to twenty times slower than natively: the longest property tests
// there take every kEmulatedStride-th of their cases. What can differ between architectures
// (rounding, fused multiply-adds, 32-bit sizes) shows in any case; the native suite runs all.
#ifdef NONEUCLID_EMULATED
inline constexpr int kEmulatedStride = 4;
#else
inline constexpr int kEmulatedStride = 1;
#endif

// Degrees to radians.
constexpr double deg(double degrees) { return degrees * (kPi / 180); }

// The angle between two directions given in radians, in [0, pi].
inline double angle_diff(double a, double b) { return std::fabs(std::remainder(a - b, 2 * kPi)); }

// The distance of two polar points (r, theta) in the flat picture (azimuthal equidistant): what
// the screen shows, and well defined at r = 0 where theta is not.
template <class P>
double plane_distance(const P& a, const P& b) {
    return std::hypot(a.r * std::cos(a.theta) - b.r * std::cos(b.theta),
                      a.r * std::sin(a.theta) - b.r * std::sin(b.theta));
}

// A polar point of any engine (fixed, float, double) in double.
template <template <class> class Polar, class T>
Polar<double> D(const Polar<T>& p) {
    return {static_cast<double>(p.r), static_cast<double>(p.theta)};
}

// A directory of the running test's own, empty, removed with this object (ctest runs the tests
// in parallel processes, and a test may want more than one).
class TempDir {
public:
    TempDir() {
        static int made = 0;
        const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
        const std::string test = t ? std::string(t->test_suite_name()) + "." + t->name() : "no-test";
        path = std::filesystem::path(::testing::TempDir()) /
               ("noneuclid-" + test + "-" + std::to_string(::getpid()) + "-" + std::to_string(++made));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string file(const std::string& name) const { return (path / name).string(); }

    std::filesystem::path path;
};

}  // namespace noneuclid::test
