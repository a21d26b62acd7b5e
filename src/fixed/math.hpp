// The fixed-point math library: every function on Q16.16 (`fixed`) the geometry uses, from
// lookup tables with linear interpolation (the paper's lookup-table idea), integer arithmetic
// only, no OS, no heap, no floating point: numbers only (the fixed-point geometry kernels built
// on them are in geometry/fx). In three parts:
//   fixed/cmath.hpp        the <cmath> set: sin, cos, atan2, asin, acos, sqrt, exp, log, sinh,
//                          cosh, asinh, acosh, hypot
//   fixed/division.hpp     exact division with or without a 64-bit divide instruction:
//                          recip_q62, div_round, Divisor (divisor, quotient, quarter), isqrt64
//   fixed/curvature.hpp    the curvature functions Sf, Cf, ASf, ATf, their products rounded once
//                          (mul_Sf, mul_ASf, mul_ATf, dot2, dot3, mul_carry)
// Each header gives its functions' domains and what happens outside them; docs/accuracy.md
// gives the measured errors (tests/accuracy asserts them). Functions are found by
// argument-dependent lookup from code templated on the scalar:
//     template <class T> T f(T x) { using std::sin; return sin(x); }
// calls std::sin for double and fx::sin for fixed.
#pragma once

#include "fixed/cmath.hpp"
#include "fixed/curvature.hpp"
#include "fixed/division.hpp"
