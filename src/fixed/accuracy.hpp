// Accuracy of the fixed-point functions against the std:: double functions.
//
// One piece of code measures, and both `noneuclid accuracy` (which prints the table) and
// tests/accuracy call it: what docs/accuracy.md reports is what the tests measure. The bounds
// the tests assert are written in tests/accuracy/test_accuracy.cpp, not here: abs_bound and
// rel_bound below are the report's own (its "ok" column and exit code), so that the test does
// not trust the code it checks.
//
// Method. Each row sweeps one function over a documented domain: `dense` evenly spaced points
// (plus as many log-spaced points for domains spanning several decades) and `random` seeded
// uniform points (rows whose domain is marked ~ add as many log-spaced points, so that every
// decade and the steep ends near domain limits are covered). Every sample is first rounded to
// the function's input type (Q16.16 or binary angle), so the error measured is that of the
// function on the exact input it was given; the std:: reference is evaluated in double on that
// same input. Rows with a rel_floor use a mixed measure, each sample counted once: relative
// error where |reference| >= floor, absolute error below it (where the Q16.16 output step,
// 1.5e-5, decides more than any function could). Rows without a floor measure absolute error
// everywhere.
#pragma once

#include <cstdint>

namespace noneuclid::fx {

struct AccuracyRow {
    const char* function;  // e.g. "sin(angle)"
    const char* domain;    // e.g. "[-pi, pi)"
    long samples;
    long abs_samples;      // how many of them the absolute error was taken over
    double max_abs;        // max |fixed - reference| (where |reference| < rel_floor, if set)
    double arg_abs[2];     // where it occurs (second value used by two-argument functions)
    double max_rel;        // max |fixed - reference| / |reference| where |reference| >= rel_floor
    double arg_rel[2];
    double rel_floor;
    double abs_bound;      // the report's bounds (0 = none): what `noneuclid accuracy` checks
    double rel_bound;      // for its ok column; tests/accuracy holds bounds of its own
    double required;       // the ceiling the project was asked for (0 = none stated)
    bool required_is_rel;
    bool two_args;
    bool pass;             // both of the report's bounds hold
};

struct AccuracyOptions {
    uint64_t seed = 20190101;  // seeds the random samples; same seed, same table
    long dense = 1 << 18;      // evenly spaced samples per row
    long random = 1 << 16;     // random samples per row
};

// Number of rows measure_accuracy() fills.
int accuracy_row_count();

// Fills rows[0 .. min(capacity, accuracy_row_count())) and returns how many it filled.
int measure_accuracy(const AccuracyOptions& options, AccuracyRow* rows, int capacity);

}  // namespace noneuclid::fx
