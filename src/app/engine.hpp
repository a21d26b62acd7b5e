// The engine a world runs on, chosen once: fixed point (the device's), double (the reference),
// float, or the paper's formulas in double. Every command that builds a world goes through
// with_engine, so adding an engine is one line here.
#pragma once

#include <string>
#include <type_traits>

#include "fixed/fixed.hpp"
#include "world/world.hpp"

namespace noneuclid::app {

enum class Engine { fixed, double_, float_, paper };

inline constexpr Engine kEngines[] = {Engine::fixed, Engine::double_, Engine::float_, Engine::paper};

inline const char* engine_name(Engine e) {
    switch (e) {
        case Engine::fixed: return "fixed";
        case Engine::double_: return "double";
        case Engine::float_: return "float";
        case Engine::paper: return "paper";
    }
    return "?";
}

inline bool parse_engine(const std::string& s, Engine& out) {
    for (Engine e : kEngines)
        if (s == engine_name(e)) {
            out = e;
            return true;
        }
    return false;
}

// Calls f(std::type_identity<W>{}) with W the world type of the engine and returns its result.
template <class F>
decltype(auto) with_engine(Engine e, F&& f) {
    switch (e) {
        case Engine::double_: return f(std::type_identity<world::World<double>>{});
        case Engine::float_: return f(std::type_identity<world::World<float>>{});
        case Engine::paper: return f(std::type_identity<world::World<double, true>>{});
        case Engine::fixed: break;
    }
    return f(std::type_identity<world::World<fx::fixed>>{});
}

}  // namespace noneuclid::app
