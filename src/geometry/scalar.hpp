// What the geometry needs of a scalar, for double and float; the fixed-point type brings its
// own (src/fixed/math.hpp) and is found by argument-dependent lookup. Geometry code is written
// once as templates in namespace noneuclid::geo and calls these unqualified:
//     using std::sin; ... sin(x), Sf(u), wrap_pi(a)
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "fixed/math.hpp"

namespace noneuclid::geo {

using fx::fixed;

template <class T>
constexpr T pi_v = T(3.14159265358979323846);

namespace detail {
// The curvature functions of docs/design.md in floating point. Series near u = 0, where the
// closed forms would divide 0 by 0; the series are truncated where the next term is below
// 1e-17.
template <class T>
T Sf(T u) {
    using std::fabs, std::sin, std::sinh, std::sqrt;
    if (fabs(u) < T(1e-3)) return T(1) - u / 6 + u * u / 120 - u * u * u / 5040;
    const T s = sqrt(fabs(u));
    return u > 0 ? sin(s) / s : sinh(s) / s;
}
template <class T>
T Cf(T u) {
    using std::cos, std::cosh, std::fabs, std::sqrt;
    if (fabs(u) < T(1e-3)) return T(1) - u / 2 + u * u / 24 - u * u * u / 720;
    const T s = sqrt(fabs(u));
    return u > 0 ? cos(s) : cosh(s);
}
// ASf(u) for u <= 1 (clamped there: S_K never exceeds 1/sqrt K but rounding may).
template <class T>
T ASf(T u) {
    using std::asin, std::asinh, std::fabs, std::sqrt;
    if (u >= 1) return pi_v<T> / 2;
    if (fabs(u) < T(1e-3)) return T(1) + u / 6 + T(3) * u * u / 40 + T(5) * u * u * u / 112;
    const T s = sqrt(fabs(u));
    return u > 0 ? asin(s) / s : asinh(s) / s;
}
// ATf(u) for u > -1 (infinite at -1).
template <class T>
T ATf(T u) {
    using std::atan, std::atanh, std::fabs, std::sqrt;
    if (fabs(u) < T(1e-3)) return T(1) - u / 3 + u * u / 5 - u * u * u / 7;
    if (u <= -1) return T(INFINITY);
    const T s = sqrt(fabs(u));
    return u > 0 ? atan(s) / s : atanh(s) / s;
}
}  // namespace detail

inline double Sf(double u) { return detail::Sf(u); }
inline float Sf(float u) { return detail::Sf(u); }
inline double Cf(double u) { return detail::Cf(u); }
inline float Cf(float u) { return detail::Cf(u); }
inline double ASf(double u) { return detail::ASf(u); }
inline float ASf(float u) { return detail::ASf(u); }
inline double ATf(double u) { return detail::ATf(u); }
inline float ATf(float u) { return detail::ATf(u); }
inline double hypot(double x, double y) { return std::sqrt(x * x + y * y); }
inline float hypot(float x, float y) { return std::sqrt(x * x + y * y); }

// sin(x/2) for x first brought into [-pi, pi] (fx::sin_half halves exactly).
inline double sin_half(double x) { return std::sin(std::remainder(x, 2 * pi_v<double>) / 2); }
inline float sin_half(float x) { return std::sin(std::remainder(x, 2 * pi_v<float>) / 2); }

// y sin(x/2) in two steps, the sine kept: sine_of_half(x), then mul_unit(y, that) (fx:: keeps
// the sine in Q2.30).
inline double sine_of_half(double x) { return sin_half(x); }
inline float sine_of_half(float x) { return sin_half(x); }
inline double mul_unit(double y, double s) { return y * s; }
inline float mul_unit(float y, float s) { return y * s; }

// x f(u) for the curvature functions; the fx:: versions round once.
inline double mul_Sf(double x, double u) { return x * Sf(u); }
inline float mul_Sf(float x, float u) { return x * Sf(u); }
inline double mul_ASf(double x, double u) { return x * ASf(u); }
inline float mul_ASf(float x, float u) { return x * ASf(u); }
inline double mul_ATf(double x, double u) { return x * ATf(u); }
inline float mul_ATf(float x, float u) { return x * ATf(u); }

// a b; fx::mul_carry carries the rounding to the next call (floating point needs no carry).
inline double mul_carry(double a, double b, int64_t&) { return a * b; }
inline float mul_carry(float a, float b, int64_t&) { return a * b; }

// a b + c d; fx::dot2 rounds once.
inline double dot2(double a, double b, double c, double d) { return a * b + c * d; }
inline float dot2(float a, float b, float c, float d) { return a * b + c * d; }

// a b + c d + e f; fx::dot3 rounds once.
inline double dot3(double a, double b, double c, double d, double e, double f) { return a * b + c * d + e * f; }
inline float dot3(float a, float b, float c, float d, float e, float f) { return a * b + c * d + e * f; }

// An angle brought into [-pi, pi].
inline double wrap_pi(double a) { return std::remainder(a, 2 * pi_v<double>); }
inline float wrap_pi(float a) { return std::remainder(a, 2 * pi_v<float>); }
inline fixed wrap_pi(fixed a) { return fx::angle::from_radians(a).to_radians(); }

// x / d for many x and one d: plain division in floating point; fx::divisor (found by ADL)
// takes the reciprocal once and gives the same bits as fixed's operator/.
template <class T>
struct FloatDivisor {
    T d;
    T operator()(T x) const { return x / d; }
};
inline FloatDivisor<double> divisor(double d) { return {d}; }
inline FloatDivisor<float> divisor(float d) { return {d}; }
inline double quotient(double a, double b) { return a / b; }
inline float quotient(float a, float b) { return a / b; }
inline double quarter(double x) { return x / 4; }
inline float quarter(float x) { return x / 4; }

// The fractions k/n and (n - k)/n for k = 0, 1, ..., n, exactly as T(k) / T(n) and
// T(n - k) / T(n) round, without a division per k in fixed point: the quotient and remainder
// of k 2^16 / n are carried from one k to the next.
template <class T>
class Fractions {
public:
    explicit Fractions(int n) : n_(n) {}
    T t(int k) const { return T(k) / T(n_); }
    T u(int k) const { return T(n_ - k) / T(n_); }
    void next() {}

private:
    int n_;
};
template <>
class Fractions<fixed> {
public:
    explicit Fractions(int n) : n_(static_cast<uint32_t>(n)), dq_(65536u / n_), dr_(65536u % n_) {}
    // For k = 0, 1, ... in turn, advanced by next(). k 2^16 = q n + r.
    fixed t(int) const { return fixed::from_raw(static_cast<int32_t>(q_ + (2 * r_ >= n_))); }
    fixed u(int) const {
        // (n - k) 2^16 = (2^16 - q) n - r: floor 2^16 - q - (r > 0), remainder n - r (or 0).
        const uint32_t fl = 65536u - q_ - (r_ > 0), rem = r_ > 0 ? n_ - r_ : 0;
        return fixed::from_raw(static_cast<int32_t>(fl + (2 * rem >= n_)));
    }
    void next() {
        q_ += dq_, r_ += dr_;
        if (r_ >= n_) r_ -= n_, ++q_;
    }

private:
    uint32_t n_, dq_, dr_, q_ = 0, r_ = 0;
};

// Converts a double constant to the scalar (compile-time for fixed).
template <class T>
constexpr T num(double v) {
    return T(v);
}

}  // namespace noneuclid::geo
