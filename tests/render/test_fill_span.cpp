// The textured run's sampler (render/fill_span.hpp) on maps whose exact values are known: every
// pixel painted once, each within half a texel of the exact map where the map is smooth, the
// exact value wherever a point in its piece cannot be shown, and a flat map sampled only at
// every kSpanStep-th pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "render/fill_span.hpp"

using namespace noneuclid::render::fill;

namespace {

struct SpanRun {
    std::vector<int> painted;      // times each pixel was painted
    std::vector<Texcoord> coords;  // what it was painted with
    long exact_calls = 0;
};
// The run [x0, x1) of a row 0..width through sampled_span with the map f (1/256 texel), shown
// where `shown` says.
SpanRun run(int width, int x0, int x1, const std::function<double(int)>& f, const std::function<bool(int)>& shown) {
    SpanRun r;
    r.painted.assign(static_cast<std::size_t>(width), 0);
    r.coords.assign(static_cast<std::size_t>(width), {});
    sampled_span(
        x0, x1,
        [&](int x, Texcoord& t) {
            ++r.exact_calls;
            if (!shown(x)) return false;
            t.s = static_cast<int64_t>(std::floor(f(x))), t.t = static_cast<int64_t>(std::floor(-0.5 * f(x)));
            return true;
        },
        [&](int x, int n, int64_t s, int64_t t, int64_t ds, int64_t dt) {
            for (int i = 0; i < n; ++i, s += ds, t += dt) {
                ++r.painted[static_cast<std::size_t>(x + i)];
                r.coords[static_cast<std::size_t>(x + i)] = {s >> 8, t >> 8};
            }
        });
    return r;
}
bool always(int) { return true; }

// The worst distance, 1/256 texel, of a painted pixel's coordinates from the exact map's.
double worst_error(const SpanRun& r, int x0, int x1, const std::function<double(int)>& f) {
    double worst = 0;
    for (int x = x0; x < x1; ++x) {
        const Texcoord t = r.coords[static_cast<std::size_t>(x)];
        worst = std::max({worst, std::abs(static_cast<double>(t.s) - std::floor(f(x))),
                          std::abs(static_cast<double>(t.t) - std::floor(-0.5 * f(x)))});
    }
    return worst;
}

TEST(FillSpan, ALinearMapIsExactAndSampledOnlyEveryStep) {
    const auto f = [](int x) { return 300.0 * x + 17; };  // 1.2 texels a pixel
    const SpanRun r = run(1000, 0, 1000, f, always);
    for (int x = 0; x < 1000; ++x) EXPECT_EQ(r.painted[static_cast<std::size_t>(x)], 1) << x;
    EXPECT_LE(worst_error(r, 0, 1000, f), 1.0);  // the chord's own rounding
    // Each piece: its end and its middle (1000 px: 31 pieces of 32 and one of 7), and the first pixel.
    EXPECT_LE(r.exact_calls, 1 + 2 * (1000 / kSpanStep + 1));
}

TEST(FillSpan, ABentMapStaysWithinHalfATexel) {
    // From 7 to 200 texels a pixel, its derivative growing toward the run's end as 1/(120 - x),
    // as a map's does toward the antipode's circle.
    const auto f = [](int x) { return 256.0 * 40 * std::log(120.0 / (120.0 - x)) * 20; };
    for (int x0 : {0, 3, 50})
        for (int x1 : {1, 2, 17, 64, 101, 117}) {
            if (x1 <= x0) continue;
            const SpanRun r = run(120, x0, x1, f, always);
            for (int x = 0; x < 120; ++x) EXPECT_EQ(r.painted[static_cast<std::size_t>(x)], x >= x0 && x < x1 ? 1 : 0) << x;
            // The middle of each piece is within kSpanError; elsewhere a bent chord's error is
            // below that at its middle, but for the map's third derivative: a margin of 1/16.
            EXPECT_LE(worst_error(r, x0, x1, f), kSpanError * 17 / 16 + 1) << x0 << ".." << x1;
        }
}

TEST(FillSpan, PiecesHoldingAPointNotShownAreTakenPixelByPixel) {
    const auto f = [](int x) { return 100.0 * x * x; };
    const auto shown = [](int x) { return x < 37 || x > 41; };  // a hole, as past the antipode's circle
    const SpanRun r = run(100, 0, 100, f, shown);
    for (int x = 0; x < 100; ++x) {
        EXPECT_EQ(r.painted[static_cast<std::size_t>(x)], shown(x) ? 1 : 0) << x;
        if (shown(x)) {
            EXPECT_LE(std::abs(static_cast<double>(r.coords[static_cast<std::size_t>(x)].s) - std::floor(f(x))), kSpanError + 1) << x;
        }
    }
}

}  // namespace
