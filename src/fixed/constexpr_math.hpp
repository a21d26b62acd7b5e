// Double-precision elementary functions usable in constant expressions, used only to build
// the lookup tables at compile time (std::sin and friends are not constexpr in C++20).
// Accurate to a few units in the last place of a double over the ranges the tables use, far
// below the 2^-30 steps the tables store. Checked against std:: in tests/unit/test_tables.cpp.
#pragma once

namespace noneuclid::fx::cx {

inline constexpr double pi = 3.141592653589793238462643383279502884;
inline constexpr double ln2 = 0.693147180559945309417232121458176568;

constexpr double abs(double x) { return x < 0 ? -x : x; }

// sin on any moderate x: reduce to [-pi, pi], then Taylor series to convergence.
constexpr double sin(double x) {
    const double two_pi = 2 * pi;
    const long long k = static_cast<long long>(x / two_pi + (x >= 0 ? 0.5 : -0.5));
    x -= static_cast<double>(k) * two_pi;
    double term = x, sum = x;
    for (int n = 1; n < 40; ++n) {
        term *= -x * x / ((2.0 * n) * (2.0 * n + 1));
        sum += term;
    }
    return sum;
}
constexpr double cos(double x) { return sin(x + pi / 2); }

// e^x: halve the argument until |x| <= 1/2, Taylor series, square back.
constexpr double exp(double x) {
    int halvings = 0;
    while (abs(x) > 0.5) {
        x /= 2;
        ++halvings;
    }
    double term = 1, sum = 1;
    for (int n = 1; n < 30; ++n) {
        term *= x / n;
        sum += term;
    }
    for (int i = 0; i < halvings; ++i) sum *= sum;
    return sum;
}

constexpr double sqrt(double x) {
    if (x <= 0) return 0;
    double r = x > 1 ? x : 1;
    for (int i = 0; i < 200; ++i) {
        const double n = 0.5 * (r + x / r);
        if (n == r) break;
        r = n;
    }
    return r;
}

// Natural log for x > 0: scale into [1, 2), then ln y = 2 atanh((y-1)/(y+1)).
constexpr double log(double x) {
    int e = 0;
    while (x >= 2) {
        x /= 2;
        ++e;
    }
    while (x < 1) {
        x *= 2;
        --e;
    }
    const double z = (x - 1) / (x + 1), z2 = z * z;
    double term = z, sum = 0;
    for (int n = 0; n < 60; ++n) {
        sum += term / (2 * n + 1);
        term *= z2;
    }
    return 2 * sum + e * ln2;
}
constexpr double log2(double x) { return log(x) / ln2; }

// atan for x >= 0: two argument halvings atan(x) = 2 atan(x / (1 + sqrt(1 + x^2))), series.
constexpr double atan(double x) {
    if (x < 0) return -atan(-x);
    if (x > 1) return pi / 2 - atan(1 / x);
    int doublings = 0;
    while (x > 0.1) {
        x = x / (1 + sqrt(1 + x * x));
        ++doublings;
    }
    double term = x, sum = 0;
    for (int n = 0; n < 40; ++n) {
        sum += term / (2 * n + 1);
        term *= -x * x;
    }
    for (int i = 0; i < doublings; ++i) sum *= 2;
    return sum;
}
constexpr double asin(double x) {
    if (x >= 1) return pi / 2;
    if (x <= -1) return -pi / 2;
    return atan(x / sqrt(1 - x * x));
}
constexpr double asinh(double x) {
    if (x < 0) return -asinh(-x);
    if (x < 0.125) {  // series: no cancellation in log(1 + small)
        double term = x, sum = 0;
        for (int n = 0; n < 30; ++n) {
            sum += term / (2 * n + 1);
            term *= -x * x * (2 * n + 1) / (2 * n + 2);
        }
        return sum;
    }
    return log(x + sqrt(x * x + 1));
}

// The curvature functions of docs/design.md as power series in u (exact for |u| <= 40 in
// double):
//   Sf(u) = sum (-u)^n / (2n+1)!   Cf(u) = sum (-u)^n / (2n)!
constexpr double Sf(double u) {
    double term = 1, sum = 1;
    for (int n = 1; n < 60; ++n) {
        term *= -u / ((2.0 * n) * (2.0 * n + 1));
        sum += term;
    }
    return sum;
}
constexpr double Cf(double u) {
    double term = 1, sum = 1;
    for (int n = 1; n < 60; ++n) {
        term *= -u / ((2.0 * n - 1) * (2.0 * n));
        sum += term;
    }
    return sum;
}
// ASf(u) = asin(sqrt u)/sqrt u (u > 0), asinh(sqrt -u)/sqrt -u (u < 0), 1 at 0.
constexpr double ASf(double u) {
    if (abs(u) < 1e-3) return 1 + u / 6 + 3 * u * u / 40 + 5 * u * u * u / 112;
    if (u > 0) return asin(sqrt(u)) / sqrt(u);
    return asinh(sqrt(-u)) / sqrt(-u);
}

// atanh for 0 <= x < 1.
constexpr double atanh(double x) {
    if (x < 0.125) {
        double term = x, sum = 0;
        for (int n = 0; n < 30; ++n) {
            sum += term / (2 * n + 1);
            term *= x * x;
        }
        return sum;
    }
    return 0.5 * log((1 + x) / (1 - x));
}
// ATf(u) = atan(sqrt u)/sqrt u (u > 0), atanh(sqrt -u)/sqrt -u (-1 < u < 0), 1 at 0.
constexpr double ATf(double u) {
    if (abs(u) < 1e-3) return 1 - u / 3 + u * u / 5 - u * u * u / 7;
    if (u > 0) return atan(sqrt(u)) / sqrt(u);
    return atanh(sqrt(-u)) / sqrt(-u);
}

// Round to nearest integer (half away from zero) for table entries.
constexpr long long round_to_ll(double v) {
    return static_cast<long long>(v >= 0 ? v + 0.5 : v - 0.5);
}

}  // namespace noneuclid::fx::cx
