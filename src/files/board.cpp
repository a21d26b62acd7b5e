#include "files/board.hpp"

#include <string>
#include <utility>
#include <vector>

#include "geometry/geometry.hpp"
#include "lang/lang.hpp"
#include "world/engines.hpp"
#include "world/palette_names.hpp"
#include "world/quote.hpp"
#include "files/text_file.hpp"
#include "files/toml_reader.hpp"

namespace noneuclid::files {
namespace {

// Every control a button may name, from the table (world/action.hpp): "thrust, left, ... or mute".
std::string control_list() {
    std::vector<std::string> names;
    for (int i = 0; i < world::kActionCount; ++i) names.emplace_back(world::action_name(static_cast<world::Action>(i)));
    return world::or_list(names);
}

using tomlr::Bad, tomlr::Reader, tomlr::tables, tomlr::type_name;

const toml::table* section(const toml::table& root, const char* key) {
    const toml::node* n = root.get(key);
    if (!n) return nullptr;
    if (const toml::table* t = n->as_table()) return t;
    throw Bad{n->source(), std::string("expected a [") + key + "] table, found " + type_name(*n)};
}

std::vector<std::string> strings(const toml::table& t, const char* key, const std::string& context) {
    std::vector<std::string> out;
    const toml::node* n = t.get(key);
    if (!n) return out;
    auto plain = [&](const toml::node& e, const std::string& v) {
        if (!world::is_plain(v)) throw Bad{e.source(), context + "expected " + world::quote(key) + " without control characters, found " + world::quote(v)};
        return v;
    };
    if (auto s = n->as_string()) return {plain(*n, s->get())};
    const toml::array* a = n->as_array();
    if (!a) throw Bad{n->source(), context + "expected a string or a list of strings for " + world::quote(key) + ", found " + type_name(*n)};
    for (const toml::node& e : *a) {
        auto s = e.as_string();
        if (!s) throw Bad{e.source(), context + "expected strings in " + world::quote(key) + ", found " + type_name(e)};
        out.push_back(plain(e, s->get()));
    }
    return out;
}

// Reads `root` over `b`: a key the file sets replaces b's value, one it leaves out keeps it (a
// fresh Board's defaults for a board file; the board's own values for an override).
void read_board(const toml::table& root, Board& b) {
    const Reader r(root, "");
    r.only({"name", "models", "display", "gpio", "evdev", "attract", "button"});
    b.name = r.plain_string("name", b.name);
    if (root.get("models")) b.models = strings(root, "models", "");
    if (const toml::table* t = section(root, "display")) {
        const Reader d(*t, "display: ");
        d.only({"device", "fps", "scene", "engine", "projection", "antialias", "hud", "palette", "large_hud", "one_button", "sound", "language", "threads"});
        b.device = d.plain_string("device", b.device);
        b.fps = d.number("fps", b.fps, 1, 1000, "frames per second");
        b.scene = d.plain_string("scene", b.scene);
        b.engine = d.string("engine", b.engine);
        world::EngineKind engine;
        if (!b.engine.empty() && (!world::parse_engine(b.engine, engine) || !world::engine_on_board(engine)))
            throw Bad{t->get("engine")->source(), "display: expected engine = " + world::or_list(world::engine_names(true), true) + ", found \"" + world::printable(b.engine) + "\""};
        b.projection = d.string("projection", b.projection);
        geo::Projection projection{};
        if (!geo::parse_projection_name(b.projection, projection))
            throw Bad{t->get("projection")->source(), "display: expected projection = " + world::or_list(geo::projection_names(), true) + ", found \"" + world::printable(b.projection) + "\""};
        b.antialias = d.boolean("antialias", b.antialias);
        b.hud = d.boolean("hud", b.hud);
        b.large_hud = d.boolean("large_hud", b.large_hud);
        b.one_button = d.boolean("one_button", b.one_button);
        b.sound = d.boolean("sound", b.sound);
        b.palette = d.string("palette", b.palette);
        world::Palette palette{};
        if (!world::parse_palette(b.palette, palette))
            throw Bad{t->get("palette")->source(), "display: expected palette = " + world::or_list(world::palette_names(), true) + ", found \"" + world::printable(b.palette) + "\""};
        b.language = d.string("language", b.language);
        lang::Language language{};
        if (!b.language.empty() && !lang::parse_language(b.language, language))
            throw Bad{t->get("language")->source(), "display: expected language = " + std::string(lang::language_choices()) + " (or \"\" for the locale's), found \"" + world::printable(b.language) + "\""};
        if (!b.language.empty()) b.language = lang::language_code(language);
        b.threads = static_cast<int>(d.integer("threads", b.threads, 1, 16, "drawing threads, 1 for the main thread only"));
    }
    if (const toml::table* t = section(root, "gpio")) {
        const Reader g(*t, "gpio: ");
        g.only({"chip", "debounce_ms"});
        if (t->get("chip")) b.chips = strings(*t, "chip", "gpio: ");
        b.debounce_ms = static_cast<int>(g.integer("debounce_ms", b.debounce_ms, 0, 1000, "milliseconds"));
    }
    if (const toml::table* t = section(root, "evdev")) {
        const Reader e(*t, "evdev: ");
        e.only({"device", "grab"});
        b.evdev_device = e.plain_string("device", b.evdev_device);
        b.grab = e.boolean("grab", b.grab);
    }
    if (const toml::table* t = section(root, "attract")) {
        const Reader a(*t, "attract: ");
        a.only({"idle_seconds", "sweep_seconds", "lesson"});
        b.attract_lesson = a.plain_string("lesson", b.attract_lesson);
        b.idle_seconds = a.number("idle_seconds", b.idle_seconds, 0, 1e7, "seconds without a button; 0 turns attract mode off");
        b.sweep_seconds = a.number("sweep_seconds", b.sweep_seconds, 4, 1e5, "seconds for K from -1 to +1");
    }
    if (const toml::array* buttons = tables(root, "button")) {
        b.buttons.clear();  // a file's buttons are the whole wiring, never added to another's
        for (const toml::node& n : *buttons) {
            const toml::table& t = *n.as_table();
            const Reader br(t, "button: ");
            br.only({"action", "gpio", "pin", "key"});
            const toml::node* a = t.get("action");
            if (!a) throw Bad{t.source(), "button: expected action = \"thrust\" (or " + control_list() + "), found none"};
            BoardButton bb;
            const std::string action = br.string("action", "");
            if (!world::parse_action(action, bb.control))
                throw Bad{a->source(), "button: unknown action \"" + world::printable(action) + "\" (expected " + control_list() + ")"};
            const Reader named(t, "button " + world::quote(action) + ": ");
            bb.gpio = static_cast<int>(named.integer("gpio", -1, 0, 1023, "line offset on the GPIO chip, the BCM number on a Raspberry Pi"));
            bb.pin = static_cast<int>(named.integer("pin", 0, 1, 40, "physical pin on the 40-pin header"));
            bb.key = static_cast<int>(named.integer("key", -1, 1, 767, "evdev key code, e.g. 57 for KEY_SPACE"));
            if (bb.gpio < 0 && bb.key < 0)
                throw Bad{t.source(), "button " + world::quote(action) + ": expected a gpio line or a key code (or both), found neither"};
            for (const BoardButton& o : b.buttons) {
                if (bb.gpio >= 0 && o.gpio == bb.gpio)
                    throw Bad{t.get("gpio")->source(), "button " + world::quote(action) + ": gpio " + std::to_string(bb.gpio) +
                                                           " is already the " + world::quote(world::action_name(o.control)) + " button"};
                if (bb.key >= 0 && o.key == bb.key)
                    throw Bad{t.get("key")->source(), "button " + world::quote(action) + ": key " + std::to_string(bb.key) +
                                                          " is already the " + world::quote(world::action_name(o.control)) + " button"};
            }
            b.buttons.push_back(bb);
        }
    }
}

}  // namespace

bool parse_board(const std::string& text, const std::string& name, Board& out, BoardError& error) {
    out = Board{};
    out.file = name;
    return tomlr::parse_toml(text, name, error, [&](const toml::table& root) { read_board(root, out); });
}

bool load_board_file(const std::string& path, Board& out, BoardError& error) {
    std::string text, why;
    if (!read_text_file(path, kBoardFileLimit, "a board file", text, why)) {
        error = {path, 0, 0, "the board file: " + why +
                                 ": check the path, or name a board in boards/ (rpi-zero2w, rpi3, rpi4, rpi5, generic)"};
        return false;
    }
    return parse_board(text, path, out, error);
}

bool overlay_board_file(const std::string& path, Board& board, BoardError& error) {
    std::string text, why;
    if (!read_text_file(path, kBoardFileLimit, "a board file", text, why)) {
        error = {path, 0, 0, "the board override: " + why + ": fix its permissions or remove it"};
        return false;
    }
    Board over = board;
    if (!tomlr::parse_toml(text, path, error, [&](const toml::table& root) { read_board(root, over); })) return false;
    board = std::move(over);
    return true;
}

}  // namespace noneuclid::files
