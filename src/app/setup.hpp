// What the world commands share between reading their options and running: the scene, the
// HUD's font, the session's options.
#pragma once

#include <memory>
#include <string>

#include "app/high_scores.hpp"
#include "app/options.hpp"
#include "app/recorder.hpp"
#include "app/platform.hpp"
#include "app/session.hpp"
#include "world/scene.hpp"

namespace noneuclid::app {

// The scene o.scene names (built in, or a TOML file), at o.curvature if given. A name that is
// neither, or a bad file, is a UsageError (one sentence, with file:line:column for a file).
world::Scene load_scene(const Options& o);
// The HUD's font (o.font: "", "builtin" or a file); a font asked for that cannot be read is a
// UsageError.
platform::LoadedFont load_font(const Options& o);
// The kind of world that runs `scene` (kinds/kinds.hpp) on o's engine, or the kind's first if o
// names none; a kind without the engine named is a UsageError naming the kind's engines.
kinds::KindChoice world_kind(const Options& o, const world::Scene& scene);
// The font as a setting: "builtin" or its file.
std::string font_setting(const platform::LoadedFont& f);
// The settings a recording starts with (o's, with the legend resolved): with them
// `render --actions FILE` draws what the run showed, bit for bit (the canvas's size and the
// frame count follow as the run goes, from the frame loop).
void record_settings(Recorder& rec, const Options& o, const std::string& display, const platform::LoadedFont& font,
                     const render::PixelFormat& format);
// The high-score table of a game (app/high_scores.hpp): the file `choice` names, or "" for the
// state directory's "scores" (platform::state_file); null for "none", or when there is no state
// directory (said in one line on stderr). Says where the table is, in one line. `play`: the
// game's own use, which sets a damaged table aside; else (`noneuclid scores`) it is only read.
// A file in a directory that does not exist, and a path that holds no table the game can use
// (anything it did not write; with !play a damaged table too) are a UsageError, except the
// state directory's in `run`, which is said in one line and not kept (the kiosk plays on).
std::unique_ptr<HighScoreTable> open_scores(const std::string& choice, bool play);
// Refuses (a UsageError, before any work) an output path that must not be written
// (platform::output_allowed: a directory, a device, a symbolic link): --out, --gif, --record
// and --screenshot.
void check_outputs(const Options& o);
// The one rule for a file a command writes (docs/reliability.md, "Outputs"): allowed there
// (app/platform.hpp's output_allowed), named with `extension` (".png"; null: any) unless it is a
// stream (a FIFO, standard output), and its missing folders made. A UsageError naming `option`
// and the fix otherwise.
void check_output(const char* option, const std::string& path, const char* extension, const char* what);
// The language o asks for: --lang (or a board's, a recording's), else the locale's
// (platform::locale_name), else English.
lang::Language resolve_language(const Options& o);

// The session's options for o, with `legend` ("keys" or "buttons") as the HUD's legend, in the
// words of the world's kind (world_kind's choice).
SessionOptions session_options(const Options& o, const world::Scene& scene, const std::string& legend,
                               kinds::KindChoice kind);

}  // namespace noneuclid::app
