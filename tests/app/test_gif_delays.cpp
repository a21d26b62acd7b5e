// render --gif's frame delays (app/gif_delays.hpp): each within the 16 bits a GIF frame's
// delay has, their sum the world time in whole centiseconds, held to exact integer arithmetic.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <limits>

#include "app/gif_delays.hpp"

using noneuclid::app::GifDelays;

// Frames of 2/60 s (render's default): 3.33 cs each, given as 3s and 4s whose running sum is
// round(n · 10/3) exactly (the reference: integer arithmetic, (20n + 3) / 6).
TEST(GifDelays, TheSumFollowsTheWorldTime) {
    GifDelays d(2.0 / 60);
    int64_t sum = 0;
    for (int64_t n = 1; n <= 100000; ++n) {
        const int cs = d.next();
        ASSERT_TRUE(cs == 3 || cs == 4) << n;
        sum += cs;
        ASSERT_EQ(sum, (20 * n + 3) / 6) << n;
    }
    EXPECT_EQ(d.total(), sum);
}

// At most 655.35 s a frame (65535 cs, render refuses more): no delay wraps past 16 bits, and a
// sum past 2³¹ centiseconds (the int it was kept in) stays exact.
TEST(GifDelays, LongFramesNeitherWrapNorOverflow) {
    GifDelays longest(655.35);
    GifDelays long_ones(600.005);  // 60000.5 cs: rounding gives 60000 and 60001 in turn
    int64_t a = 0, b = 0;
    constexpr int64_t kFrames = 40000;
    for (int64_t n = 1; n <= kFrames; ++n) {
        const int x = longest.next(), y = long_ones.next();
        ASSERT_EQ(x, 65535) << n;
        ASSERT_TRUE(y == 60000 || y == 60001) << n;
        a += x, b += y;
    }
    EXPECT_EQ(a, 65535 * kFrames);
    EXPECT_GT(a, std::numeric_limits<int32_t>::max());
    EXPECT_EQ(longest.total(), a);
    // 40000 × 60000.5 cs, within the centisecond that 600.005 s in binary can move a rounding.
    EXPECT_LE(std::llabs(b - 2400020000LL), 1);
}

// Frames shorter than 2 cs are shown for 2 (what viewers take as the shortest), and the sum
// then runs ahead of the world time, never below it.
TEST(GifDelays, AtLeastTwoCentiseconds) {
    GifDelays d(1e-4);
    for (int n = 1; n <= 1000; ++n) ASSERT_EQ(d.next(), 2) << n;
    EXPECT_EQ(d.total(), 2000);
}
