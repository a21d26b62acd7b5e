// The kinds of world, one row each (the contract: kinds/kind.hpp): its name, its line in the
// docs and `noneuclid scenes`, which scenes it takes (accepts), what it can do (Capabilities),
// and the engines it runs on, each with the kind's type on that engine. The session, the C
// interface, the firmware, dump, render and the web page choose a world here (choose_kind) and
// build it here (with_kind), so a new kind of world is a row of this table and a folder of its
// own (docs/design.md, "Adding to it").
//
// A scene goes to the first row that accepts it. The engine is the one asked for if the kind
// has it (an error naming the kind's engines if not), else the kind's first.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "kinds/constant.hpp"
#include "kinds/kind.hpp"
#include "kinds/space.hpp"
#include "kinds/uneven.hpp"
#include "world/engines.hpp"
#include "world/quote.hpp"

namespace noneuclid::kinds {

// What a kind can do beyond the contract (each user checks the flag it needs).
struct Capabilities {
    bool threads = false;      // draws over a pool of threads (--threads); else on one
    bool c_interface = false;  // the C interface (src/capi) runs it
    bool firmware = false;     // the microcontroller firmware (platform/mcu) runs it
};

// Kind K on engine E.
template <world::EngineKind E, WorldKind K>
struct On {
    static constexpr world::EngineKind engine = E;
    using kind = K;
};

template <class... Ons>
struct KindRow {
    const char* name;
    const char* help;
    bool (*accepts)(const world::Scene&);
    Capabilities can;
    static constexpr std::size_t kEngines = sizeof...(Ons);
    // std::array, not a C array: clang 14 takes a pack-sized static C array member as incomplete.
    static constexpr std::array<world::EngineKind, sizeof...(Ons)> kEngineList{Ons::engine...};
    using ons = std::tuple<Ons...>;
};

// The world of constant K on every engine of world/engines.hpp, in that table's order.
template <std::size_t... I>
auto constant_row_type(std::index_sequence<I...>)
    -> KindRow<On<world::EngineKind{I}, Constant<typename std::tuple_element_t<I, world::EngineTable>::world>>...>;
using ConstantRow = decltype(constant_row_type(std::make_index_sequence<world::kEngineCount>{}));

inline bool constant_accepts(const world::Scene& s) { return s.bumps.empty() && !s.space; }
inline bool uneven_accepts(const world::Scene& s) { return !s.bumps.empty() && !s.space; }
inline bool space_accepts(const world::Scene& s) { return s.space; }

inline constexpr std::tuple kKindTable{
    ConstantRow{"constant", "a world of constant curvature K, the paper's (every scene without [[bump]] tables)",
                constant_accepts, {.threads = true, .c_interface = true, .firmware = true}},
    KindRow<On<world::engine_named("double"), Uneven>>{
        "uneven", "a world whose curvature varies from place to place (a scene with [[bump]] tables, docs/uneven.md)",
        uneven_accepts, {}},
    KindRow<On<world::engine_named("fixed"), SpaceOn<fx::fixed>>, On<world::engine_named("double"), SpaceOn<double>>>{
        "space", "a three-dimensional space of constant curvature K (the space, 8-cell and order-5-cubic scenes, or [[solid]] "
        "tables; docs/space.md)", space_accepts, {}},
};
using KindTable = std::remove_const_t<decltype(kKindTable)>;
inline constexpr std::size_t kKindCount = std::tuple_size_v<KindTable>;

// A kind of the table on one of its engines.
struct KindChoice {
    std::size_t kind = 0;
    world::EngineKind engine = world::kDefaultEngine;
};

namespace detail {
template <std::size_t I = 0, class F>
decltype(auto) visit_row(std::size_t kind, F&& f) {
    if constexpr (I + 1 == kKindCount) {
        return f(std::get<I>(kKindTable));
    } else {
        if (kind == I) return f(std::get<I>(kKindTable));
        return visit_row<I + 1>(kind, f);
    }
}
template <class Ons, std::size_t J = 0, class F>
decltype(auto) visit_on(world::EngineKind e, F&& f) {
    using O = std::tuple_element_t<J, Ons>;
    if constexpr (J + 1 == std::tuple_size_v<Ons>) {
        return f(std::type_identity<typename O::kind>{});
    } else {
        if (e == O::engine) return f(std::type_identity<typename O::kind>{});
        return visit_on<Ons, J + 1>(e, f);
    }
}
}  // namespace detail

// f(row) for kind `kind`'s row (a kind past the table is the last).
template <class F>
decltype(auto) visit_kind(std::size_t kind, F&& f) {
    return detail::visit_row(kind, f);
}
inline const char* kind_name(std::size_t kind) {
    return visit_kind(kind, [](const auto& row) { return row.name; });
}
inline const char* kind_help(std::size_t kind) {
    return visit_kind(kind, [](const auto& row) { return row.help; });
}
inline Capabilities kind_can(std::size_t kind) {
    return visit_kind(kind, [](const auto& row) { return row.can; });
}
// The names of kind `kind`'s engines, in its row's order (its first is its default).
inline std::vector<std::string> kind_engines(std::size_t kind) {
    return visit_kind(kind, [](const auto& row) {
        std::vector<std::string> names;
        for (world::EngineKind e : row.kEngineList) names.emplace_back(world::engine_name(e));
        return names;
    });
}
inline bool kind_has_engine(std::size_t kind, world::EngineKind e) {
    return visit_kind(kind, [&](const auto& row) {
        for (world::EngineKind x : row.kEngineList)
            if (x == e) return true;
        return false;
    });
}

// A kind's first engine, its default.
inline world::EngineKind kind_engines_first(std::size_t kind) {
    return visit_kind(kind, [](const auto& row) { return row.kEngineList[0]; });
}

// The kind that takes `scene`, on `*engine` if given, else on its first engine. False, with
// `why` one sentence naming the kind and its engines, if it has not that engine.
inline bool choose_kind(const world::Scene& scene, const world::EngineKind* engine, KindChoice& out, std::string& why) {
    std::size_t k = 0;
    while (k + 1 < kKindCount && !visit_kind(k, [&](const auto& row) { return row.accepts(scene); })) ++k;
    out.kind = k;
    if (!engine) {
        out.engine = kind_engines_first(k);
        return true;
    }
    if (!kind_has_engine(k, *engine)) {
        why = std::string("the scene is ") + kind_help(k) + ", which runs on the " + world::or_list(kind_engines(k)) +
              " engine, not on " + world::engine_name(*engine);
        return false;
    }
    out.engine = *engine;
    return true;
}

// Calls f(std::type_identity<K>{}) with K the kind type of choice c, and returns its result.
template <class F>
decltype(auto) with_kind(KindChoice c, F&& f) {
    return visit_kind(c.kind, [&](const auto& row) -> decltype(auto) {
        using Ons = typename std::remove_cvref_t<decltype(row)>::ons;
        return detail::visit_on<Ons>(c.engine, f);
    });
}

// with_kind for the kinds whose Capabilities have the flag Can only (the others' types are not
// built, so a user links only what it runs): f(std::type_identity<K>{}) and true, or false for a
// kind without the flag.
template <bool Capabilities::*Can, std::size_t I = 0, class F>
bool with_kind_that_can(KindChoice c, F&& f) {
    if constexpr (I == kKindCount) {
        return false;
    } else {
        constexpr const auto& row = std::get<I>(kKindTable);
        if constexpr (row.can.*Can) {
            if (c.kind == I) {
                detail::visit_on<typename std::remove_cvref_t<decltype(row)>::ons>(c.engine, f);
                return true;
            }
        }
        return with_kind_that_can<Can, I + 1>(c, f);
    }
}

}  // namespace noneuclid::kinds
