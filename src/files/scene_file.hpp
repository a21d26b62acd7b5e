// Scene files in TOML (parsed with toml++). The format (docs/file-formats.md, "Scene files"):
//
//     curvature = -1.0            # K in [-1, 1]
//     limit_radius = 3.14159      # R in world units
//     [[body]]
//     name = "ship"
//     position = [0.5, 30.0]      # [r, theta deg]
//     facing = 90.0               # degrees, in the frame carried from O
//     velocity = [0.2, 90.0]      # [speed in world units per second, direction deg]
//     spin = 0.0                  # degrees per second
//     color = "#ff4040"
//     closed = true
//     tessellation = 8
//     vertices = [[0.1, 0.0], [0.1, 140.0], [0.1, 220.0]]   # local [rho, phi deg] from facing
//
// plus, all optional: presets = [...], thrust, turn_rate, curvature_rate, sweep_rate at the top;
// acceleration = [a, direction deg], controlled, grid, fill = "#rrggbb", texture = "file.png",
// texture_scale, texture_filter in a body; [[grid]] tables
// (kind = "axes" with spacing, or "radial" with lines; length, step, color).
#pragma once

#include <functional>
#include <string>

#include "world/image.hpp"
#include "world/scene.hpp"

namespace noneuclid::files {

struct SceneError {
    std::string file;
    long line = 0, column = 0;  // 1-based; 0 when the error has no place (e.g. unreadable file)
    std::string message;        // what was expected and what was found
    // "file:line:column: message" (or "file: message")
    std::string to_string() const;
};

// Reads the image file at `path` for a texture (texture = "file.png"; app/setup.cpp reads PNG
// through the platform). False with one sentence (no full stop) in `why`: what is wrong with
// the image and how to fix it. Built-in images ("builtin:...") never reach it.
using ImageReader = std::function<bool(const std::string& path, world::Image& out, std::string& why)>;

// The identity of the file at `path` (app/setup.cpp: its device and inode, from the platform),
// "" if there is none: two paths with one identity name one file, decoded once.
using FileIdentity = std::function<std::string(const std::string& path)>;

// Reads a scene file. On failure returns false and fills `error`. A texture's file is read with
// `images`, its path taken relative to the scene file's directory, once per path and, with
// `identify`, once per file; without a reader only the built-in images can be named. The
// images decoded are held to the world's budget (world/budget.hpp) as they are read.
bool load_scene_file(const std::string& path, world::Scene& out, SceneError& error, const ImageReader& images = {},
                     const FileIdentity& identify = {});
// The same from a string (`name` is used in messages in place of a path, and as the path that
// textures are relative to).
bool parse_scene(const std::string& text, const std::string& name, world::Scene& out, SceneError& error,
                 const ImageReader& images = {}, const FileIdentity& identify = {});

}  // namespace noneuclid::files
