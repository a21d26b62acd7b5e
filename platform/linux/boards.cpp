#include "linux/boards.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace noneuclid::platform {
namespace fs = std::filesystem;
namespace {
// boards/generic.toml, read into the binary at build time.
#include "generic_board.inc"
}  // namespace

std::vector<std::string> board_dirs() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("NONEUCLID_BOARDS"); env && *env) dirs.push_back(env);
#ifdef NONEUCLID_BOARDS_INSTALL_DIR
    dirs.push_back(NONEUCLID_BOARDS_INSTALL_DIR);
#endif
#ifdef NONEUCLID_BOARDS_SOURCE_DIR
    dirs.push_back(NONEUCLID_BOARDS_SOURCE_DIR);
#endif
    return dirs;
}

bool load_board(const std::string& spec, files::Board& out, std::string& error) {
    files::BoardError e;
    const bool is_path = spec.find('/') != std::string::npos || (spec.size() > 5 && spec.ends_with(".toml"));
    if (is_path) {
        if (files::load_board_file(spec, out, e)) return true;
        error = e.to_string();
        return false;
    }
    std::string looked;
    for (const std::string& d : board_dirs()) {
        const fs::path p = fs::path(d) / (spec + ".toml");
        std::error_code ec;
        if (fs::is_regular_file(p, ec)) {
            if (files::load_board_file(p.string(), out, e)) return true;
            error = e.to_string();
            return false;
        }
        looked += (looked.empty() ? "" : ", ") + d;
    }
    if (spec == "generic") {  // no boards directory (a binary copied on its own): built in
        if (files::parse_board(kGenericBoard, "generic (built in)", out, e)) return true;
        error = e.to_string();
        return false;
    }
    error = "no board named '" + spec + "' in " + (looked.empty() ? std::string("any boards directory") : looked) +
            ": use rpi-zero2w, rpi3, rpi4, rpi5 or generic, give a board file's path, or set NONEUCLID_BOARDS to the directory";
    return false;
}

bool detect_board(files::Board& out, std::string& why, std::string& error) {
    std::string model;
    {
        std::ifstream in("/proc/device-tree/model", std::ios::binary);
        if (in) model.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        while (!model.empty() && (model.back() == '\0' || model.back() == '\n')) model.pop_back();
    }
    if (!model.empty()) {
        for (const std::string& d : board_dirs()) {
            std::error_code ec;
            for (const fs::directory_entry& f : fs::directory_iterator(d, ec)) {
                if (f.path().extension() != ".toml") continue;
                files::Board b;
                files::BoardError e;
                if (!files::load_board_file(f.path().string(), b, e)) continue;
                for (const std::string& m : b.models)
                    if (!m.empty() && model.compare(0, m.size(), m) == 0) {
                        out = b;
                        why = "board " + f.path().stem().string() + " (" + f.path().string() + "), because this machine is a " + model;
                        return true;
                    }
            }
        }
    }
    if (!load_board("generic", out, error)) return false;
    why = "board generic (" + out.file + "), because " +
          (model.empty() ? std::string("this machine has no device-tree model") : "no board file lists the model '" + model + "'") +
          "; choose one with --board";
    return true;
}

}  // namespace noneuclid::platform

namespace noneuclid::platform {

std::string board_override_path() {
    if (const char* env = std::getenv("NONEUCLID_BOARD_OVERRIDE")) return env;
#ifdef NONEUCLID_BOARD_OVERRIDE
    return NONEUCLID_BOARD_OVERRIDE;
#else
    return "";
#endif
}

bool find_board(const std::string& spec, files::Board& out, std::string& note, std::string& error) {
    if (spec.empty()) {
        if (!detect_board(out, note, error)) return false;
    } else {
        if (!load_board(spec, out, error)) return false;
        note = "board " + out.name + " (" + out.file + ")";
    }
    // The kiosk's local settings, over whichever board it is: a file that is not there is no
    // override (the package ships one that sets nothing).
    const std::string over = board_override_path();
    std::error_code ec;
    if (over.empty() || !fs::exists(over, ec)) return true;
    files::BoardError e;
    if (!files::overlay_board_file(over, out, e)) {
        error = e.to_string();
        return false;
    }
    note += ". " + over + " is read over it";
    return true;
}

}  // namespace noneuclid::platform
