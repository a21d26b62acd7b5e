// No heap allocation per frame in steady state: a counting global operator new, switched on
// only around the frames, while the world steps and the whole frame is drawn (fixed and double
// engines, kiosk and stress, aliased and anti-aliased, every pixel format), on one thread and
// over a WorkerPool of 2 and 3 threads (the counter is global and atomic: it sees the workers'
// allocations too; the pool and its scratch are made before counting starts, once).
#include <gtest/gtest.h>

#include <vector>

#include "render/draw_world.hpp"
#include "render/parallel_frame.hpp"
#include "render/hud.hpp"
#include "render/layout.hpp"
#include "render/measure_panel.hpp"
#include "app/frame_loop.hpp"
#include "app/memory_display.hpp"
#include "counting_new.hpp"
#include "uneven/draw.hpp"

namespace {

using namespace noneuclid;

template <class T>
long allocations_per_frames(const char* scene_name, render::PixelFormat f, bool aa, int frames, int threads = 0) {
    world::Scene scene;
    const world::SceneParams params{30, 6, 6};
    EXPECT_TRUE(world::builtin_scene(scene_name, params, scene));
    world::World<T> w(scene);
    render::DrawScratch<T> scratch;
    scratch.prepare(w);
    render::WorkerPool pool(threads > 0 ? threads : 1);
    render::ParallelScratch<T> par;
    par.prepare(w, pool);
    auto draw = [&](const render::Canvas& c, const render::DrawOptions& o) {
        if (threads > 0)
            render::draw_world(c, w, o, par, pool);
        else
            render::draw_world(c, w, o, scratch);
    };
    std::vector<uint8_t> px(static_cast<std::size_t>(320 * 240 * f.bytes_per_pixel()));
    const render::Canvas c(px.data(), 320, 240, 320 * f.bytes_per_pixel(), f);
    render::DrawOptions o;
    o.antialias = aa;
    render::HudInfo hud;
    w.press(world::Action::thrust);  // the ship accelerates: the velocity path runs too
    w.press(world::Action::curvature_down);
    for (int i = 0; i < 3; ++i) w.step(1.0 / 60), draw(c, o);  // warm up
    test::start_counting();
    for (int i = 0; i < frames; ++i) {
        w.step(1.0 / 60);
        draw(c, o);
        hud.K = static_cast<double>(w.K);
        render::draw_hud(c, render::builtin_font(), hud, render::layout_hud(320, 240, render::builtin_font(), hud));
    }
    return test::stop_counting();
}

TEST(NoAllocation, SteadyStateFramesAllocateNothing) {
    for (const char* s : {"kiosk", "stress", "fig17", "textured"})
        for (bool aa : {false, true}) {
            EXPECT_EQ(allocations_per_frames<fx::fixed>(s, render::PixelFormat::rgb565(), aa, 120), 0) << s;
            EXPECT_EQ(allocations_per_frames<double>(s, render::PixelFormat::xrgb8888(), aa, 120), 0) << s;
            EXPECT_EQ(allocations_per_frames<float>(s, render::PixelFormat::rgb888(), aa, 60), 0) << s;
        }
}

// The Earth: thousands of vertices, K turning every frame (every shape cache rebuilt), in both
// projections' paths. (Fewer frames than above: each draws them all.)
TEST(NoAllocation, TheEarthAllocatesNothingPerFrame) {
    for (bool aa : {false, true}) {
        EXPECT_EQ(allocations_per_frames<fx::fixed>("earth", render::PixelFormat::rgb565(), aa, 20), 0);
        EXPECT_EQ(allocations_per_frames<double>("earth", render::PixelFormat::xrgb8888(), aa, 20), 0);
    }
}

TEST(NoAllocation, ThreadedFramesAllocateNothing) {
    for (const char* s : {"kiosk", "stress", "textured"})
        for (int threads : {2, 3}) {
            EXPECT_EQ(allocations_per_frames<fx::fixed>(s, render::PixelFormat::rgb565(), false, 120, threads), 0) << s;
            EXPECT_EQ(allocations_per_frames<double>(s, render::PixelFormat::xrgb8888(), true, 60, threads), 0) << s;
            EXPECT_EQ(allocations_per_frames<float>(s, render::PixelFormat::rgb888(), false, 30, threads), 0) << s;
        }
}

// The instruments while K changes every frame and the live one cycles through every instrument
// and takes marks (world/instruments.hpp), their panels drawn (render/measure_panel.hpp).
template <class T>
long instrument_allocations() {
    world::Scene scene;
    EXPECT_TRUE(world::builtin_scene("measure", {}, scene));
    world::MeasureDecl polygon;
    polygon.kind = geo::Instrument::polygon;
    scene.measures.push_back(polygon);
    world::World<T> w(scene);
    render::DrawScratch<T> scratch;
    scratch.prepare(w);
    std::vector<uint8_t> px(800 * 480 * 4);
    const render::Canvas c(px.data(), 800, 480, 800 * 4, render::PixelFormat::xrgb8888());
    w.press(world::Action::thrust);
    w.press(world::Action::curvature_down);
    w.step(1.0 / 60), render::draw_world(c, w, {}, scratch);
    test::start_counting();
    for (int i = 0; i < 400; ++i) {
        if (i % 100 == 0) w.press(world::Action::instrument), w.release(world::Action::instrument);
        if (i % 9 == 0) w.press(world::Action::fire), w.release(world::Action::fire);
        if (i == 200) w.release(world::Action::curvature_down), w.press(world::Action::curvature_up);
        w.step(1.0 / 60);
        render::draw_world(c, w, {}, scratch);
        render::HudInfo panels;
        panels.on = false;
        for (const auto& g : w.gauges()) panels.panels += g.on() && panels.panels < 2;
        const render::HudLayout l = render::layout_hud(c.width(), c.height(), render::builtin_font(), panels);
        int side = 0;
        for (const auto& g : w.gauges())
            if (g.on() && side < 2)
                render::draw_measure_panel(c, render::builtin_font(), render::measure_panel(g.reading()), l.panel[side++],
                                           l.panel_scale);
    }
    return test::stop_counting();
}

TEST(NoAllocation, TheInstrumentsAllocateNothingPerFrame) {
    EXPECT_EQ(instrument_allocations<fx::fixed>(), 0);
    EXPECT_EQ(instrument_allocations<double>(), 0);
}

// The counter does count: a frame that builds a vector is seen.
TEST(NoAllocation, TheCounterSeesAnAllocation) {
    test::start_counting();
    std::vector<int> v(10);
    EXPECT_GE(test::stop_counting(), 1);
    EXPECT_EQ(v.size(), 10u);
}

}  // namespace

// The frame loop as `noneuclid run` runs it (app::FrameLoop on the headless display, a session
// with the HUD, attract mode and keys queued each frame): nothing allocated per frame either.
namespace {

class KeysDisplay final : public app::Display {
public:
    render::Canvas canvas() override { return inner_.canvas(); }
    void present() override { inner_.present(); }
    bool wait(int64_t, app::InputSink& sink) override {
        const long f = inner_.presented();
        sink.input({world::Action::thrust, f % 40 < 20});
        sink.input({world::Action::fire, f % 30 < 25});  // (the game: starts it, then shots)
        sink.input({world::Action::left, f % 90 < 30});
        if (f % 50 == 0) sink.input({world::Action::projection, true}), sink.input({world::Action::projection, false});
        return true;
    }
    bool closing() const override { return false; }
    bool realtime() const override { return false; }
    bool read_back(app::Picture& out, std::string& e) override { return inner_.read_back(out, e); }
    const char* legend() const override { return "keys"; }

private:
    app::MemoryDisplay inner_{320, 240, render::PixelFormat::rgb565()};
};

// Each frame's sound rendered, as a platform's SoundOut does (app/sound.hpp): the synthesiser
// allocates nothing either.
class SynthOut final : public app::SoundOut {
public:
    void frame(const app::SoundFrame& f, double seconds) override {
        synth_.apply(f);
        synth_.render(samples_, static_cast<int>(seconds * synth_.rate() + 0.5));
        rendered_ += synth_.active();
    }
    long rendered_ = 0;  // frames with something sounding

private:
    app::Synth synth_{44100};
    int16_t samples_[4096] = {};
};

long loop_allocations(world::EngineKind engine, int threads, const char* scene_name = "kiosk") {
    world::Scene scene;
    EXPECT_TRUE(world::builtin_scene(scene_name, {}, scene));
    app::SessionOptions so;
    so.hud = true, so.show_fps = true, so.legend = "keys", so.threads = threads;
    so.attract = {2, 10, 0.25};  // attract mode comes and goes with the keys
    kinds::KindChoice kind;
    std::string why;
    EXPECT_TRUE(kinds::choose_kind(scene, &engine, kind, why)) << why;
    const auto session = app::make_session(kind, scene, so, render::builtin_font(), nullptr);
    KeysDisplay display;
    app::LoopOptions lo;
    lo.frames = 400;
    app::FrameLoop loop(display, *session, nullptr, nullptr, lo);
    SynthOut sound;
    loop.set_sound(&sound);
    for (int i = 0; i < 3; ++i) loop.tick();  // warm up
    test::start_counting();
    long frames = 0;
    while (loop.tick()) ++frames;
    const long allocations = test::stop_counting();
    EXPECT_EQ(frames, 397);
    EXPECT_GT(sound.rendered_, 0) << "the keys thrust and fire: something sounded";
    return allocations;
}

TEST(NoAllocation, TheFrameLoopAllocatesNothingPerFrame) {
    EXPECT_EQ(loop_allocations(world::engine_named("fixed"), 1), 0);
    EXPECT_EQ(loop_allocations(world::engine_named("double"), 2), 0);
}

// The game: shots, hits, splits (new outlines in the asteroids' slots), crashes and attract
// mode's play, without an allocation.
TEST(NoAllocation, TheGameAllocatesNothingPerFrame) {
    EXPECT_EQ(loop_allocations(world::engine_named("fixed"), 1, "asteroids"), 0);
    EXPECT_EQ(loop_allocations(world::engine_named("double"), 2, "asteroids"), 0);
}

// The ship flown over the Earth (the earth scene's, by the same keys) in the frame loop.
TEST(NoAllocation, TheShipOverTheEarthAllocatesNothingPerFrame) {
    EXPECT_EQ(loop_allocations(world::engine_named("fixed"), 1, "earth"), 0);
    EXPECT_EQ(loop_allocations(world::engine_named("double"), 2, "earth"), 0);
}

// The three-dimensional world (src/space) in the frame loop: the keys fly the ship, P switches
// its two views.
TEST(NoAllocation, TheThreeDimensionalWorldAllocatesNothingPerFrame) {
    EXPECT_EQ(loop_allocations(world::engine_named("double"), 1, "space"), 0);  // (its one engine)
}

// An uneven world (src/uneven): in the frame loop with the keys, and in both views with its
// bumps' strength and K turned every frame, so that every cache (the field, the fan, the
// inhabitant's view's table, the grid lines' outlines) is rebuilt every frame, the live
// triangle marked and measured again each frame.
TEST(NoAllocation, AnUnevenWorldAllocatesNothingPerFrame) {
    for (const char* name : {"lens", "hills"}) {
        EXPECT_EQ(loop_allocations(world::engine_named("double"), 1, name), 0) << name;  // (its one engine)
        world::Scene scene;
        ASSERT_TRUE(world::builtin_scene(name, {}, scene));
        for (bool chart : {true, false}) {
            uneven::World w(scene);
            uneven::Drawing d;
            d.prepare(w);
            std::vector<uint8_t> px(320 * 240 * 2);
            const render::Canvas c(px.data(), 320, 240, 320 * 2, render::PixelFormat::rgb565());
            render::DrawOptions o;
            o.projection = chart ? geo::Projection::stereographic : geo::Projection::azimuthal_equidistant;
            w.press(world::Action::strength_up), w.press(world::Action::curvature_down), w.press(world::Action::thrust);
            for (int i = 0; i < 3; ++i) w.step(1.0 / 60), d.draw(c, w, o, true);  // warm up
            test::start_counting();
            w.press(world::Action::instrument), w.release(world::Action::instrument);  // the live triangle, marked
            for (int i = 0; i < 40; ++i) {
                if (i % 8 == 0) w.press(world::Action::fire), w.release(world::Action::fire);
                w.step(1.0 / 60), d.draw(c, w, o, i % 2 == 0);
            }
            EXPECT_EQ(test::stop_counting(), 0) << name << (chart ? " chart" : " inhabitant's view");
        }
    }
}

}  // namespace
