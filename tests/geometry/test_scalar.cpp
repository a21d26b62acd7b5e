// The scalar helpers the engines share (geometry/scalar.hpp) against the arithmetic they stand
// for, bit for bit: geo::Fractions<fixed>, the fractions k/n and (n - k)/n along an edge carried
// from one k to the next without a division, against T(k) / T(n) (fx::fixed's operator/ itself
// is held to its definition in tests/fixed/test_division.cpp).
#include <gtest/gtest.h>

#include "geometry/scalar.hpp"

namespace {

using namespace noneuclid;
using fx::fixed;

TEST(FastPaths, FractionsAreTheQuotients) {
    for (int n = 1; n < 3000; n += (n < 300 ? 1 : 37)) {
        geo::Fractions<fixed> f(n);
        for (int k = 1; k < n; ++k) {
            f.next();
            ASSERT_EQ(f.t(k).raw(), (fixed(k) / fixed(n)).raw()) << k << "/" << n;
            ASSERT_EQ(f.u(k).raw(), (fixed(n - k) / fixed(n)).raw()) << n - k << "/" << n;
        }
    }
}

}  // namespace
