// The engines a world can run on (geometry/engine.hpp), one row each: its name (the command
// line's --engine, a board file's engine, a recording's setting), its line in --help, whether
// a kiosk's board file may choose it, and its world type. Everything that names engines reads
// this table, and with_engine builds a world of a row's type, so adding an engine is its policy
// and one row here.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "fixed/fixed.hpp"
#include "geometry/engine.hpp"
#include "world/world.hpp"

namespace noneuclid::world {

template <class W>
struct EngineRow {
    using world = W;
    const char* name;
    const char* help;
    bool board;  // a board file may choose it
};

inline constexpr std::tuple kEngineTable{
    EngineRow<World<fx::fixed>>{"fixed", "fixed point and lookup tables, the device's (the default)", true},
    EngineRow<World<double>>{"double", "the same exact forms in double, the reference", true},
    EngineRow<World<float>>{"float", "the same exact forms in float", true},
    EngineRow<World<double, geo::Paper>>{"paper", "the paper's formulas, literally, in double", false},
};
inline constexpr std::size_t kEngineCount = std::tuple_size_v<decltype(kEngineTable)>;

// An engine: its row in kEngineTable.
struct EngineKind {
    std::size_t index = 0;
    friend constexpr bool operator==(EngineKind, EngineKind) = default;
};

using EngineTable = std::remove_const_t<decltype(kEngineTable)>;

// f(row) for engine e's row (a row past the table is the first).
template <std::size_t I = 0, class F>
constexpr decltype(auto) visit_engine(EngineKind e, F&& f) {
    if constexpr (I + 1 == kEngineCount) {
        return f(std::get<I>(kEngineTable));
    } else {
        if (e.index == I) return f(std::get<I>(kEngineTable));
        return visit_engine<I + 1>(e, f);
    }
}

constexpr const char* engine_name(EngineKind e) {
    return visit_engine(e, [](const auto& row) { return row.name; });
}
constexpr const char* engine_help(EngineKind e) {
    return visit_engine(e, [](const auto& row) { return row.help; });
}
constexpr bool engine_on_board(EngineKind e) {
    return visit_engine(e, [](const auto& row) { return row.board; });
}
// The engine named `name`; false if none is.
constexpr bool parse_engine(std::string_view name, EngineKind& out) {
    for (std::size_t i = 0; i < kEngineCount; ++i)
        if (name == engine_name(EngineKind{i})) return out = EngineKind{i}, true;
    return false;
}
// Never defined: a call in a constant expression is a compile error (engine_named's, without
// the exceptions the firmware builds without).
void no_engine_of_that_name_in_kEngineTable();
// The engine of a name the code itself uses (a compile error if no row has it).
consteval EngineKind engine_named(std::string_view name) {
    EngineKind e;
    if (!parse_engine(name, e)) no_engine_of_that_name_in_kEngineTable();
    return e;
}
inline constexpr EngineKind kDefaultEngine = engine_named("fixed");

// The engines' names, in the table's order (a board's: those it may choose).
inline std::vector<std::string> engine_names(bool board_only = false) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < kEngineCount; ++i)
        if (!board_only || engine_on_board(EngineKind{i})) names.emplace_back(engine_name(EngineKind{i}));
    return names;
}

// Calls f(std::type_identity<W>{}) with W the world type of engine e, and returns its result.
template <std::size_t I = 0, class F>
decltype(auto) with_engine(EngineKind e, F&& f) {
    using W = typename std::tuple_element_t<I, EngineTable>::world;
    if constexpr (I + 1 == kEngineCount) {
        return f(std::type_identity<W>{});
    } else {
        if (e.index == I) return f(std::type_identity<W>{});
        return with_engine<I + 1>(e, f);
    }
}

}  // namespace noneuclid::world
