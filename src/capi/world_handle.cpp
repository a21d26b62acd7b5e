// A WorldHandle for each kind of world the C interface runs, on each engine (see world_handle.hpp).
#include "capi/world_handle.hpp"

#include <cstdio>
#include <vector>

#include "files/dump.hpp"
#include "kinds/step.hpp"
#include "render/worker_pool.hpp"
#include "render/play.hpp"

namespace noneuclid::capi {
namespace {

// Copies `s` into out[size] with its NUL, cut to fit, leaving out control bytes (as the dump does).
void copy_text(char* out, std::size_t size, const std::string& s) {
    std::size_t n = 0;
    for (char c : s) {
        if (n + 1 >= size) break;
        if (static_cast<unsigned char>(c) >= 0x20) out[n++] = c;
    }
    out[n] = '\0';
}

template <kinds::WorldKind WK>
class KindWorld final : public WorldHandle {
public:
    using T = typename WK::World::scalar;

    explicit KindWorld(const world::Scene& scene) : kind_(scene) {
        kind_.prepare(one_thread_);
        shown_.reserve(world_.bodies.size());
        list_bodies();
    }

    void step(long steps) override {
        for (long i = 0; i < steps; ++i) world_.step(kinds::kStepSeconds);
        list_bodies();
    }
    double time() const override { return world_.time; }
    long frame() const override { return world_.frame; }
    double curvature() const override { return static_cast<double>(world_.K); }
    void set_curvature(double K) override { world_.K = T(K); }

    void control(world::Action a, bool pressed) override {
        if (render::apply_action(world_, a, pressed) == render::Applied::nothing) return;
        list_bodies();  // (reset, a new game: other bodies)
    }

    void draw(const render::Canvas& c, const render::DrawOptions& o) override {
        kind_.draw(c, o, true, one_thread_);
    }

    int body_count() const override { return static_cast<int>(shown_.size()); }
    void body(int index, nw_body& out) const override {
        const world::Body<T>& b = world_.bodies[shown_[static_cast<std::size_t>(index)]];
        const world::BodyKind kind = b.desc->kind();
        if (b.serial != 0) {
            std::snprintf(out.name, sizeof out.name, "%s %lu", world::kind_name(kind), static_cast<unsigned long>(b.serial));
        } else {
            copy_text(out.name, sizeof out.name, b.desc->name);
        }
        std::snprintf(out.kind, sizeof out.kind, "%s", world::kind_name(kind));
        using files::detail::degrees;
        out.r = static_cast<double>(b.centre.r);
        out.theta = degrees(static_cast<double>(b.centre.theta));
        out.facing = degrees(static_cast<double>(b.facing));
        out.speed = static_cast<double>(b.speed);
        out.travel = degrees(static_cast<double>(b.travel));
        out.vertices = static_cast<int>(b.local.size());
    }

    nw_game game() const override {
        const auto& g = world_.game();
        nw_game out{};
        out.on = g.on() ? 1 : 0;
        out.phase = static_cast<int>(g.phase);
        out.score = g.score;
        out.lives = g.lives;
        out.level = g.level;
        return out;
    }
    int event_count() const override { return world_.game().event_count(); }
    nw_event event(int index) const override {
        const world::GameEvent& e = world_.game().events()[index];
        nw_event out{};
        out.kind = static_cast<int>(e.kind);
        out.value = e.value;
        out.bullet = e.bullet;
        out.asteroid = e.asteroid;
        return out;
    }

private:

    // The active bodies' indices, into the room reserved for all of them: no allocation.
    void list_bodies() {
        shown_.clear();
        for (std::size_t i = 0; i < world_.bodies.size(); ++i)
            if (world_.bodies[i].active) shown_.push_back(i);
    }

    WK kind_;
    typename WK::World& world_ = kind_.world;
    render::WorkerPool one_thread_{1};
    std::vector<std::size_t> shown_;
};

}  // namespace

bool capi_engine(world::EngineKind engine) {
    return engine == world::engine_named("fixed") || engine == world::engine_named("double");
}

std::unique_ptr<WorldHandle> make_world_handle(kinds::KindChoice kind, const world::Scene& scene) {
    std::unique_ptr<WorldHandle> made;  // (none for a kind the C interface does not run)
    kinds::with_kind_that_can<&kinds::Capabilities::c_interface>(
        kind, [&]<class WK>(std::type_identity<WK>) { made = std::make_unique<KindWorld<WK>>(scene); });
    return made;
}

}  // namespace noneuclid::capi
