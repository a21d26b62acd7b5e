// The functions compared by bench_fixed (Google Benchmark, x86) and insn_probe (instruction
// counts under qemu on aarch64/armhf): each fixed-point function beside the std:: double and
// float functions that do the same job, on the same inputs. Shared so that both measure the
// same thing.
#pragma once

#include <cmath>
#include <cstdint>

#include "fixed/math.hpp"

namespace noneuclid::bench {

using fx::angle;
using fx::fixed;

// The curvature functions as the double / float geometry would compute them from std::.
template <class T>
T std_Sf(T u) {
    using std::sin, std::sinh, std::sqrt, std::fabs;
    if (fabs(u) < T(1e-4)) return T(1) - u / T(6);
    const T s = sqrt(fabs(u));
    return u > 0 ? sin(s) / s : sinh(s) / s;
}
template <class T>
T std_Cf(T u) {
    using std::cos, std::cosh, std::sqrt, std::fabs;
    const T s = sqrt(fabs(u));
    return u >= 0 ? cos(s) : cosh(s);
}
template <class T>
T std_ASf(T u) {
    using std::asin, std::asinh, std::sqrt, std::fabs;
    if (fabs(u) < T(1e-4)) return T(1) + u / T(6);
    const T s = sqrt(fabs(u));
    return u > 0 ? asin(s) / s : asinh(s) / s;
}

// One row of the comparison: a name, an input domain, and the three implementations.
// Every implementation takes two inputs (the second is used only by atan2).
struct Function {
    const char* name;
    double lo, hi;            // first argument's domain
    double lo2, hi2;          // second argument's domain (atan2)
    int32_t (*fixed_fn)(int32_t, int32_t);  // raw Q16.16 (or binary angle) in and out
    double (*double_fn)(double, double);
    float (*float_fn)(float, float);
    bool angle_input;         // fixed version takes a binary angle (sin, cos)
};

inline constexpr Function kFunctions[] = {
    {"sin", -3.14159, 3.14159, 0, 0,
     [](int32_t a, int32_t) { return sin(angle::from_raw(static_cast<uint32_t>(a))).raw(); },
     [](double x, double) { return std::sin(x); }, [](float x, float) { return std::sin(x); }, true},
    {"cos", -3.14159, 3.14159, 0, 0,
     [](int32_t a, int32_t) { return cos(angle::from_raw(static_cast<uint32_t>(a))).raw(); },
     [](double x, double) { return std::cos(x); }, [](float x, float) { return std::cos(x); }, true},
    {"atan2", -100, 100, -100, 100,
     [](int32_t y, int32_t x) { return static_cast<int32_t>(fx::atan2_angle(y, x).raw()); },
     [](double y, double x) { return std::atan2(y, x); },
     [](float y, float x) { return std::atan2(y, x); }, false},
    {"asin", -1, 1, 0, 0, [](int32_t x, int32_t) { return asin(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std::asin(x); }, [](float x, float) { return std::asin(x); }, false},
    {"acos", -1, 1, 0, 0, [](int32_t x, int32_t) { return acos(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std::acos(x); }, [](float x, float) { return std::acos(x); }, false},
    {"sqrt", 0, 1000, 0, 0, [](int32_t x, int32_t) { return sqrt(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std::sqrt(x); }, [](float x, float) { return std::sqrt(x); }, false},
    {"exp", -5, 5, 0, 0, [](int32_t x, int32_t) { return exp(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std::exp(x); }, [](float x, float) { return std::exp(x); }, false},
    {"log", 0.01, 1000, 0, 0, [](int32_t x, int32_t) { return log(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std::log(x); }, [](float x, float) { return std::log(x); }, false},
    {"sinh", -5, 5, 0, 0, [](int32_t x, int32_t) { return sinh(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std::sinh(x); }, [](float x, float) { return std::sinh(x); }, false},
    {"cosh", -5, 5, 0, 0, [](int32_t x, int32_t) { return cosh(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std::cosh(x); }, [](float x, float) { return std::cosh(x); }, false},
    {"asinh", -100, 100, 0, 0, [](int32_t x, int32_t) { return asinh(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std::asinh(x); }, [](float x, float) { return std::asinh(x); }, false},
    {"acosh", 1, 100, 0, 0, [](int32_t x, int32_t) { return acosh(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std::acosh(x); }, [](float x, float) { return std::acosh(x); }, false},
    {"Sf", -10, 10, 0, 0, [](int32_t x, int32_t) { return Sf(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std_Sf(x); }, [](float x, float) { return std_Sf(x); }, false},
    {"Cf", -10, 10, 0, 0, [](int32_t x, int32_t) { return Cf(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std_Cf(x); }, [](float x, float) { return std_Cf(x); }, false},
    {"ASf", -10, 1, 0, 0, [](int32_t x, int32_t) { return ASf(fixed::from_raw(x)).raw(); },
     [](double x, double) { return std_ASf(x); }, [](float x, float) { return std_ASf(x); }, false},
};
inline constexpr int kFunctionCount = sizeof(kFunctions) / sizeof(kFunctions[0]);

// 1024 inputs spread over a domain by a fixed sequence (same on every machine), so that table
// look-ups touch the whole table and branches are not all predicted the same way.
inline constexpr int kInputs = 1024;
struct Inputs {
    int32_t fixed_raw[kInputs], fixed_raw2[kInputs];
    double d[kInputs], d2[kInputs];
    float f[kInputs], f2[kInputs];
};
inline void make_inputs(const Function& fn, Inputs& in) {
    uint32_t s = 12345;
    auto next = [&s] {
        s = s * 1664525u + 1013904223u;
        return (s >> 8) * (1.0 / 16777216.0);
    };
    for (int i = 0; i < kInputs; ++i) {
        const double x = fn.lo + (fn.hi - fn.lo) * next();
        const double y = fn.lo2 + (fn.hi2 - fn.lo2) * next();
        if (fn.angle_input) {
            in.fixed_raw[i] = static_cast<int32_t>(angle::from_radians(x).raw());
            in.d[i] = angle::from_radians(x).to_radians_double();
        } else {
            in.fixed_raw[i] = fixed(x).raw();
            in.d[i] = fixed(x).to_double();
        }
        in.fixed_raw2[i] = fixed(y).raw();
        in.d2[i] = fixed(y).to_double();
        in.f[i] = static_cast<float>(in.d[i]);
        in.f2[i] = static_cast<float>(in.d2[i]);
    }
}

}  // namespace noneuclid::bench
