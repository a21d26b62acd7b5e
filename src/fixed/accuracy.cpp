#include "fixed/accuracy.hpp"

#include <cmath>

#include "fixed/math.hpp"

namespace noneuclid::fx {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- independent references, in double, from std:: -------------------------------------
double ref_Sf(double u) {
    if (std::fabs(u) < 1e-4) return 1 - u / 6 + u * u / 120;
    const double s = std::sqrt(std::fabs(u));
    return u > 0 ? std::sin(s) / s : std::sinh(s) / s;
}
double ref_Cf(double u) {
    const double s = std::sqrt(std::fabs(u));
    return u >= 0 ? std::cos(s) : std::cosh(s);
}
double ref_ASf(double u) {
    if (u >= 1) return kPi / 2;
    if (std::fabs(u) < 1e-4) return 1 + u / 6 + 3 * u * u / 40;
    const double s = std::sqrt(std::fabs(u));
    return u > 0 ? std::asin(s) / s : std::asinh(s) / s;
}
double ref_ATf(double u) {
    if (std::fabs(u) < 1e-4) return 1 - u / 3 + u * u / 5;
    const double s = std::sqrt(std::fabs(u));
    return u > 0 ? std::atan(s) / s : std::atanh(s) / s;
}

// ---- the fixed-point functions, seen from double ----------------------------------------

double q_fixed(double x) { return fixed(x).to_double(); }
double q_angle(double x) { return angle::from_radians(x).to_radians_double(); }
template <fixed (*F)(fixed)>
double via_fixed(double x) {
    return F(fixed(x)).to_double();
}

struct Spec {
    const char* function;
    const char* domain;
    double lo, hi;
    bool log_spaced;
    double (*quantize)(double);
    double (*fx)(double);
    double (*ref)(double);
    double rel_floor, abs_bound, rel_bound, required;
    bool required_is_rel;
};

// Bounds: the report's (abs_bound / rel_bound, its "ok" column) are what this implementation
// reaches, rounded up with a small margin; `required` is the ceiling the foundation issue set.
// The tests do not read them: tests/accuracy/test_accuracy.cpp asserts a table of its own.
const Spec kSpecs[] = {
    {"sin(angle)", "[-pi, pi)", -kPi, kPi, false, q_angle,
     [](double x) { return sin(angle::from_radians(x)).to_double(); },
     [](double x) { return std::sin(x); }, 0, 9e-6, 0, 3e-5, false},
    {"cos(angle)", "[-pi, pi)", -kPi, kPi, false, q_angle,
     [](double x) { return cos(angle::from_radians(x)).to_double(); },
     [](double x) { return std::cos(x); }, 0, 9e-6, 0, 3e-5, false},
    {"sin(x)", "[-100, 100] rad", -100, 100, false, q_fixed, via_fixed<sin>,
     [](double x) { return std::sin(x); }, 0, 9e-6, 0, 3e-5, false},
    {"cos(x)", "[-100, 100] rad", -100, 100, false, q_fixed, via_fixed<cos>,
     [](double x) { return std::cos(x); }, 0, 9e-6, 0, 3e-5, false},
    {"asin", "[-1, 1] ~", -1, 1, true, q_fixed, via_fixed<asin>,
     [](double x) { return std::asin(x); }, 0, 9e-6, 0, 2e-4, false},
    {"acos", "[-1, 1] ~", -1, 1, true, q_fixed, via_fixed<acos>,
     [](double x) { return std::acos(x); }, 0, 9e-6, 0, 2e-4, false},
    {"sqrt", "[0, 32767] ~", 0, 32767, true, q_fixed, via_fixed<sqrt>,
     [](double x) { return std::sqrt(x); }, 0.5, 7.7e-6, 1.6e-5, 2e-5, true},
    {"exp", "[-11, 10.39]", -11, 10.39, false, q_fixed, via_fixed<exp>,
     [](double x) { return std::exp(x); }, 1, 7.7e-6, 7.7e-6, 0, true},
    {"log", "(0, 32767] ~", 0, 32767, true, q_fixed, via_fixed<log>,
     [](double x) { return std::log(x); }, 0, 9e-6, 0, 0, false},
    {"sinh", "[-5, 5] ~", -5, 5, true, q_fixed, via_fixed<sinh>,
     [](double x) { return std::sinh(x); }, 1, 7.7e-6, 7.7e-6, 1e-4, true},
    {"sinh", "[-10.39, 10.39]", -10.39, 10.39, false, q_fixed, via_fixed<sinh>,
     [](double x) { return std::sinh(x); }, 1, 7.7e-6, 7.7e-6, 1e-4, true},
    {"cosh", "[-5, 5]", -5, 5, false, q_fixed, via_fixed<cosh>,
     [](double x) { return std::cosh(x); }, 1, 7.7e-6, 7.7e-6, 1e-4, true},
    {"cosh", "[-11.09, 11.09]", -11.09, 11.09, false, q_fixed, via_fixed<cosh>,
     [](double x) { return std::cosh(x); }, 1, 7.7e-6, 7.7e-6, 1e-4, true},
    {"asinh", "[-100, 100] ~", -100, 100, true, q_fixed, via_fixed<asinh>,
     [](double x) { return std::asinh(x); }, 0, 9e-6, 0, 1e-4, false},
    {"asinh", "[-32767, 32767] ~", -32767, 32767, true, q_fixed, via_fixed<asinh>,
     [](double x) { return std::asinh(x); }, 0, 9e-6, 0, 1e-4, false},
    {"acosh", "[1, 100] ~", 1, 100, true, q_fixed, via_fixed<acosh>,
     [](double x) { return std::acosh(x); }, 0, 9e-6, 0, 1e-4, false},
    {"acosh", "[1, 32767] ~", 1, 32767, true, q_fixed, via_fixed<acosh>,
     [](double x) { return std::acosh(x); }, 0, 9e-6, 0, 1e-4, false},
    // The geometry's range: K x^2 with |K| <= 1 and x <= pi, the limit radius (the tables).
    {"Sf", "[-10, 10] ~", -10, 10, true, q_fixed, via_fixed<Sf>, ref_Sf, 0, 9.5e-6, 0, 2e-5,
     false},
    // Distances up to 2 pi (across the whole disk).
    {"Sf", "[-40, 40]", -40, 40, false, q_fixed, via_fixed<Sf>, ref_Sf, 0, 9.5e-6, 0, 2e-5,
     false},
    {"Sf", "[-160, 1000]", -160, 1000, false, q_fixed, via_fixed<Sf>, ref_Sf, 1, 9.5e-6, 8.5e-6,
     0, false},
    {"Cf", "[-10, 10] ~", -10, 10, true, q_fixed, via_fixed<Cf>, ref_Cf, 0, 9.5e-6, 0, 2e-5,
     false},
    {"Cf", "[-40, 40]", -40, 40, false, q_fixed, via_fixed<Cf>, ref_Cf, 0, 1.1e-5, 0, 2e-5,
     false},
    {"Cf", "[-120, 1000]", -120, 1000, false, q_fixed, via_fixed<Cf>, ref_Cf, 1, 9.5e-6, 8.5e-6,
     0, false},
    {"ASf", "[-4, 1] ~", -4, 1, true, q_fixed, via_fixed<ASf>, ref_ASf, 0, 9e-6, 0, 2e-5,
     false},
    {"ASf", "[-140, 1] ~", -140, 1, true, q_fixed, via_fixed<ASf>, ref_ASf, 0, 9e-6, 0, 2e-5,
     false},
    {"ASf", "[-32767, 1] ~", -32767, 1, true, q_fixed, via_fixed<ASf>, ref_ASf, 0, 9e-6, 0, 0,
     false},
    // ATf(K t^2) for t = T_K(r/2): u = -tanh^2(r/2) >= -0.8437 for r <= pi at K = -1.
    {"ATf", "[-0.8437, 1] ~", -0.8437, 1, true, q_fixed, via_fixed<ATf>, ref_ATf, 0, 9e-6, 0, 2e-5,
     false},
    {"ATf", "[-0.999, 1000] ~", -0.999, 1000, true, q_fixed, via_fixed<ATf>, ref_ATf, 1, 1e-5,
     1e-5, 0, false},
};
constexpr int kSpecCount = sizeof(kSpecs) / sizeof(kSpecs[0]);
constexpr int kAtan2Rows = 2;

// splitmix64: a small, well-mixed, seedable generator (no <random> state to carry).
struct Rng {
    uint64_t s;
    uint64_t next() {
        uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform(double lo, double hi) {  // [lo, hi]
        return lo + (hi - lo) * (static_cast<double>(next() >> 11) * 0x1.0p-53);
    }
};

struct Tally {
    AccuracyRow* row;
    void add(double x, double y, double got, double want, double abs_err) {
        ++row->samples;
        if (!std::isfinite(got)) abs_err = got;  // a NaN or inf must fail, never hide
        if (row->rel_floor > 0 && std::fabs(want) >= row->rel_floor) {
            const double rel = abs_err / std::fabs(want);
            if (!(rel <= row->max_rel)) {
                row->max_rel = rel;
                row->arg_rel[0] = x;
                row->arg_rel[1] = y;
            }
        } else if (++row->abs_samples, !(abs_err <= row->max_abs)) {
            row->max_abs = abs_err;
            row->arg_abs[0] = x;
            row->arg_abs[1] = y;
        }
    }
};

void finish(AccuracyRow& r) {
    r.pass = (r.abs_bound == 0 || r.max_abs <= r.abs_bound) &&
             (r.rel_bound == 0 || r.max_rel <= r.rel_bound);
}

void measure_one(const Spec& s, const AccuracyOptions& o, uint64_t seed, AccuracyRow& r) {
    r = AccuracyRow{s.function, s.domain, 0, 0, 0, {0, 0}, 0, {0, 0}, s.rel_floor, s.abs_bound,
                    s.rel_bound, s.required, s.required_is_rel, false, false};
    Tally t{&r};
    auto sample = [&](double x) {
        if (x < s.lo) x = s.lo;
        if (x > s.hi) x = s.hi;
        const double xq = s.quantize(x);
        if (xq < s.lo || xq > s.hi) return;  // rounding pushed it out of the domain
        const double got = s.fx(xq), want = s.ref(xq);
        if (!std::isfinite(want)) return;  // e.g. log(0): outside the stated open domain
        t.add(xq, 0, got, want, std::fabs(got - want));
    };
    const long n = o.dense;
    for (long k = 0; k < n; ++k) sample(s.lo + (s.hi - s.lo) * static_cast<double>(k) / (n - 1));
    if (s.log_spaced) {
        // Geometric spacing of the distance from the domain's low end (or from 0 for a domain
        // symmetric about 0), from one Q16.16 step up: covers every decade evenly.
        const bool symmetric = s.lo < 0 && s.hi > 0;
        const double a = 1.0 / 65536, b = symmetric ? s.hi : s.hi - s.lo;
        for (long k = 0; k < n; ++k) {
            const double m = a * std::pow(b / a, static_cast<double>(k) / (n - 1));
            if (symmetric)
                sample(k % 2 ? -m : m);
            else
                sample(s.lo + m);
        }
    }
    Rng rng{seed};
    for (long k = 0; k < o.random; ++k) sample(rng.uniform(s.lo, s.hi));
    finish(r);
}

double wrap_pi(double d) {
    while (d > kPi) d -= 2 * kPi;
    while (d < -kPi) d += 2 * kPi;
    return d;
}

// atan2 over |x|, |y| <= 30000: dense points on circles of radii from one Q16.16 step to
// 30000, random points at log-uniform scales. Error is the wrapped angular difference.
void measure_atan2(bool to_angle, const AccuracyOptions& o, uint64_t seed, AccuracyRow& r) {
    r = AccuracyRow{to_angle ? "atan2 -> angle" : "atan2", "|x|,|y| <= 30000", 0, 0, 0, {0, 0}, 0,
                    {0, 0}, 0, to_angle ? 4e-7 : 8.4e-6, 0, 5e-5, false, true, false};
    Tally t{&r};
    auto sample = [&](double y, double x) {
        const fixed fy(y), fx_(x);
        const double yq = fy.to_double(), xq = fx_.to_double();
        if (yq == 0 && xq == 0) return;  // direction undefined; atan2(0,0) = 0 is a unit test
        const double got = to_angle ? atan2_angle(fy, fx_).to_radians_double()
                                    : atan2(fy, fx_).to_double();
        const double want = std::atan2(yq, xq);
        t.add(yq, xq, got, want, std::fabs(wrap_pi(got - want)));
    };
    const long rings = 16, per_ring = o.dense / rings;
    for (long k = 0; k < rings; ++k) {
        const double rad = std::pow(2.0, -16.0 + 31.0 * static_cast<double>(k) / (rings - 1));
        for (long j = 0; j < per_ring; ++j) {
            const double th = 2 * kPi * static_cast<double>(j) / per_ring;
            sample(rad * std::sin(th), rad * std::cos(th));
        }
    }
    Rng rng{seed};
    for (long k = 0; k < o.random; ++k) {
        const double scale = std::pow(2.0, rng.uniform(-14, 14.87));
        sample(rng.uniform(-scale, scale), rng.uniform(-scale, scale));
    }
    finish(r);
}

}  // namespace

int accuracy_row_count() { return kSpecCount + kAtan2Rows; }

int measure_accuracy(const AccuracyOptions& options, AccuracyRow* rows, int capacity) {
    // The circular functions first (sin, cos, then atan2), then the rest in table order.
    constexpr int kCircular = 4;
    int n = 0;
    for (int i = 0; i < kSpecCount + kAtan2Rows && n < capacity; ++i) {
        const uint64_t seed = options.seed + static_cast<uint64_t>(i);
        if (i < kCircular)
            measure_one(kSpecs[i], options, seed, rows[n++]);
        else if (i < kCircular + kAtan2Rows)
            measure_atan2(i == kCircular, options, seed, rows[n++]);
        else
            measure_one(kSpecs[i - kAtan2Rows], options, seed, rows[n++]);
    }
    return n;
}

}  // namespace noneuclid::fx
