// A game loop (docs/library.md): the Asteroids scene, its controls pressed at set times as a
// player would, stepped 60 times a second, the game's events printed as they come.
// tests/library checks them against `noneuclid dump --actions tests/files/data/game_actions.txt`,
// which holds the same presses.
//
//   example_game [FRAMES]        (600: ten seconds)
#include <cstdio>
#include <cstdlib>
#include <iterator>

#include "fixed/fixed.hpp"
#include "world/world.hpp"

int main(int argc, char** argv) {
    using namespace noneuclid::world;
    Scene scene;
    builtin_scene("asteroids", SceneParams{}, scene);
    World<noneuclid::fx::fixed> w(scene);
    struct Press { double time; Action action; bool down; };
    const Press presses[] = {{0.1, Action::fire, true}, {0.1, Action::fire, false},  // fire starts a game
                             {0.5, Action::fire, true}, {0.5, Action::left, true}};
    std::size_t next = 0;
    const char* const kinds[] = {"start", "hit", "crash", "level", "over"};
    const long frames = argc > 1 ? std::atol(argv[1]) : 600;
    while (w.frame < frames) {
        for (; next < std::size(presses) && presses[next].time <= w.time + 1e-9; ++next)
            presses[next].down ? w.press(presses[next].action) : w.release(presses[next].action);
        w.step(1.0 / 60);
        for (int i = 0; i < w.game().event_count(); ++i) {
            const GameEvent& e = w.game().events()[i];
            std::printf("frame %ld: %s bullet %u asteroid %u value %ld\n", w.frame, kinds[e.kind], e.bullet,
                        e.asteroid, e.value);
        }
    }
    std::printf("frame %ld: score %ld lives %d level %d\n", w.frame, w.game().score, w.game().lives, w.game().level);
}
