// The game's random numbers and the shapes it draws with them. Integer arithmetic only, so a
// seed gives the same game on every machine and in every engine: a recording replays bit for
// bit (the draws are doubles made from 24 integer bits, exact, then converted to the engine's
// scalar where they are used).
#pragma once

#include <cstdint>

namespace noneuclid::world {

// xorshift32 (Marsaglia), seeded through a mix so that nearby seeds give unrelated games.
class GameRandom {
public:
    GameRandom() = default;
    explicit GameRandom(uint32_t seed) { reseed(seed); }
    void reseed(uint32_t seed) {
        uint32_t x = seed * 0x9E3779B9u + 0x7F4A7C15u;  // never 0 after the mix below
        x ^= x >> 16, x *= 0x85EBCA6Bu, x ^= x >> 13, x *= 0xC2B2AE35u, x ^= x >> 16;
        state_ = x ? x : 0x6D2B79F5u;
    }
    uint32_t next() {
        uint32_t x = state_;
        x ^= x << 13, x ^= x >> 17, x ^= x << 5;
        return state_ = x;
    }
    // Uniform in [0, 1), in steps of 2^-24.
    double unit() { return static_cast<double>(next() >> 8) * (1.0 / 16777216.0); }
    // Uniform in [lo, hi).
    double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
    uint32_t state() const { return state_; }

private:
    uint32_t state_ = 0x6D2B79F5u;
};

// An asteroid's outline: n vertices counter-clockwise around its centre, each at an angle
// jittered by up to 0.3 of the even spacing and a distance from 0.7 to 1.2 times the size.
// So the polygon is irregular but star-shaped about the centre (geometry/collision.hpp): each
// wedge spans at most 1.6 / n of a turn, below half a turn for n >= 4. Writes rho and phi (in
// radians) into rho[0..n) and phi[0..n); returns the largest rho (the bounding radius).
inline double asteroid_outline(GameRandom& rng, int n, double size, double* rho, double* phi) {
    constexpr double kTurn = 6.283185307179586;
    double most = 0;
    for (int i = 0; i < n; ++i) {
        phi[i] = (i + 0.3 * rng.range(-1, 1)) * kTurn / n;
        rho[i] = size * rng.range(0.7, 1.2);
        if (rho[i] > most) most = rho[i];
    }
    return most;
}

}  // namespace noneuclid::world
