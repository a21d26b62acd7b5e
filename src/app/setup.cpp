#include "app/setup.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>
#include <utility>

#include "app/commands.hpp"
#include "world/budget.hpp"
#include "world/quote.hpp"
#include "world/ranges.hpp"
#include "files/scene_file.hpp"

namespace noneuclid::app {

world::Scene load_scene(const Options& o) {
    if (o.params.tissot && o.scene != "earth")
        usage_error("--tissot draws Tissot's circles on the Earth: it needs --scene earth, not '" + o.scene + "'.");
    world::Scene scene;
    std::string over;
    if (!world::builtin_scene(o.scene, o.params, scene, &over)) {
        if (!over.empty()) usage_error(over + " (--bodies, --vertices, --tessellation).");
        files::SceneError err;
        if (!files::load_scene_file(o.scene, scene, err, platform::read_texture, platform::file_identity)) {
            std::error_code ec;
            if (err.line == 0 && o.scene.find('/') == std::string::npos && o.scene.find(".toml") == std::string::npos &&
                !std::filesystem::exists(std::filesystem::symlink_status(o.scene, ec))) {
                usage_error("no built-in scene '" + o.scene + "' and no scene file by that name: the built-in scenes are " +
                            world::or_list(world::builtin_scene_names()) + " ('noneuclid scenes' says what each shows).");
            }
            usage_error(err.to_string());
        }
    }
    if (!world::within_budget(scene, over)) usage_error(o.scene + ": the scene: " + over + ".");
    if (!world::within_ranges(scene, over)) usage_error(o.scene + ": the scene: " + over + ".");
    if (o.has_curvature) scene.curvature = o.curvature;
    return scene;
}

kinds::KindChoice world_kind(const Options& o, const world::Scene& scene) {
    kinds::KindChoice kind;
    std::string why;
    if (!kinds::choose_kind(scene, o.engine ? &*o.engine : nullptr, kind, why))
        usage_error(o.scene + ": " + why + ": leave --engine out (it runs on the " +
                    world::engine_name(kinds::kind_engines_first(kind.kind)) + " engine then).");
    return kind;
}

platform::LoadedFont load_font(const Options& o) {
    platform::LoadedFont font;
    std::string error;
    if (!platform::hud_font(o.font, font, error)) usage_error(error);
    return font;
}

std::string font_setting(const platform::LoadedFont& f) {
    return f.bytes.empty() ? std::string("builtin") : f.source;
}

void record_settings(Recorder& rec, const Options& o, const std::string& display, const platform::LoadedFont& font,
                     const render::PixelFormat& format) {
    rec.comment(std::string("noneuclid ") + version() + " run on the " + display + " display; replay with");
    rec.comment("  noneuclid render --actions THIS_FILE --out replay.png");
    std::error_code ec;
    const bool file = o.scene.find('/') != std::string::npos || o.scene.ends_with(".toml");
    rec.setting("scene", file ? std::filesystem::absolute(o.scene, ec).string() : o.scene);
    if (o.scene == "earth") {
        char centre[64];
        std::snprintf(centre, sizeof centre, "%.17g,%.17g", o.params.centre_lat, o.params.centre_lon);
        rec.setting("centre", centre);
        if (o.params.view_km > 0) rec.setting("view", std::to_string(o.params.view_km));
        if (o.params.tissot) rec.setting("tissot", "on");
    }
    if (o.has_curvature) rec.setting("curvature", std::to_string(o.curvature));
    if (o.engine) rec.setting("engine", world::engine_name(*o.engine));
    rec.setting("projection", geo::projection_name(o.projection));
    rec.setting("aa", o.aa ? "on" : "off");
    rec.setting("hud", o.hud ? "on" : "off");
    if (o.palette != render::Palette::scene) rec.setting("palette", render::palette_name(o.palette));
    if (o.large_hud) rec.setting("large-hud", "on");
    if (o.hud_scale > 0) rec.setting("hud-scale", std::to_string(o.hud_scale));
    rec.setting("lang", lang::language_code(resolve_language(o)));
    rec.setting("legend", o.legend.empty() ? "buttons" : o.legend);
    rec.setting("font", font_setting(font));
    for (const render::PixelFormat& f : render::kNamedFormats)
        if (f.same_layout(format)) rec.setting("format", f.name);
    if (o.best > 0) rec.setting("best", std::to_string(o.best));
    if (o.stats) rec.comment("the HUD's frame rate (--stats) is wall-clock time: a replay leaves it out");
}

std::unique_ptr<HighScoreTable> open_scores(const std::string& choice, bool play) {
    if (choice == "none") return nullptr;
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::path(choice).parent_path();
    if (!choice.empty() && !dir.empty() && !std::filesystem::is_directory(dir, ec))
        usage_error("--scores " + choice + ": there is no directory " + dir.string() +
                    ": make it, or give a file in one that exists (or none).");
    std::string path = choice, error;
    if (path.empty()) path = platform::state_file("scores", error);
    if (path.empty()) {
        std::fprintf(stderr, "noneuclid: the high scores are not kept: %s.\n", error.c_str());
        return nullptr;
    }
    auto table = std::make_unique<HighScoreTable>(path);
    if (!table->load(play, error)) {
        // A table named on the command line, or one to print, is the user's to fix; the state
        // directory's is the kiosk's, which plays on without one.
        if (!choice.empty() || !play) usage_error(error);
        std::fprintf(stderr, "noneuclid: the high scores are not kept: %s\n", error.c_str());
        return nullptr;
    }
    std::fprintf(stderr, "noneuclid: high scores in %s (best %ld).\n", world::quote(table->path(), world::kPathLimit).c_str(), table->best());
    return table;
}

void check_output(const char* option, const std::string& path, const char* extension, const char* what) {
    std::string error;
    if (!platform::output_allowed(path, error)) usage_error(std::string(option) + ": " + error);
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    const bool stream = fs::exists(st) && !fs::is_regular_file(st);  // a FIFO, standard output: no name to check
    if (extension && !stream) {
        std::string ext = fs::path(path).extension().string();
        for (char& ch : ext) ch = static_cast<char>(ch >= 'A' && ch <= 'Z' ? ch - 'A' + 'a' : ch);
        if (ext != extension)
            usage_error(std::string(option) + " writes " + what + ": name it " + extension + ", not '" +
                        world::printable(path) + "'.");
    }
    const fs::path dir = fs::path(path).parent_path();
    if (stream || dir.empty() || fs::is_directory(dir, ec)) return;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        usage_error(std::string(option) + ": cannot make the folder '" + world::printable(dir.string()) + "' (" +
                    ec.message() + "): name a folder that can be made or exists.");
}

void check_outputs(const Options& o) {
    struct Output {
        const char* option;
        const std::string* path;
        const char* extension;  // null: any name
        const char* what;
    };
    const Output outputs[] = {{"--out", &o.out, ".png", "a PNG"},
                              {"--gif", &o.gif, ".gif", "an animated GIF"},
                              {"--record", &o.record, nullptr, "a recording"},
                              {"--screenshot", &o.screenshot, ".png", "a PNG"}};
    for (const Output& out : outputs)
        if (!out.path->empty()) check_output(out.option, *out.path, out.extension, out.what);
}

lang::Language resolve_language(const Options& o) {
    lang::Language l = lang::Language::en;
    if (!o.language.empty()) lang::parse_language(o.language, l);
    else lang::parse_language(platform::locale_name(), l);
    return l;
}

SessionOptions session_options(const Options& o, const world::Scene& scene, const std::string& legend,
                               kinds::KindChoice kind) {
    SessionOptions so;
    so.draw.projection = o.projection;
    so.draw.antialias = o.aa;
    so.draw.line_width = static_cast<int32_t>(o.line_width * render::kSub + 0.5);
    so.hud = o.hud;
    so.large_hud = o.large_hud;
    so.hud_scale = o.hud_scale;
    so.caption = o.caption, so.title = o.title;
    so.panels = o.panels;
    so.one_button = o.one_button;
    so.draw.palette = o.palette;
    const render::PaletteFrame frame = render::palette_frame(o.palette);
    so.draw.background = frame.background, so.draw.outside = frame.outside, so.draw.rim = frame.rim;
    so.show_fps = o.stats;
    // A scene file by its name alone: the HUD shows the same words however the path was spelt
    // (typed relative in a run, absolute in its recording), so a replay draws the same pixels.
    so.scene_name = std::filesystem::path(scene.name).filename().string();
    so.language = resolve_language(o);
    using lang::Text;
    const bool keys = legend == "keys";
    Text words = kinds::with_kind(kind, [&]<class WK>(std::type_identity<WK>) { return WK::legend(keys, scene); });
    if (o.one_button) words = scene.game.on ? Text::legend_one_button_game : Text::legend_one_button;
    so.legend = lang::text(words, so.language);
    so.attract.idle_seconds = o.attract;
    so.attract.sweep_seconds = o.sweep;
    so.threads = o.threads;
    so.dt = o.dt;
    so.best = o.best;
    return so;
}

}  // namespace noneuclid::app
