// The command line: one reader for every command's words, with one error path. A bad word is a
// UsageError carrying one sentence; main prints "noneuclid: <sentence>" and exits 2.
#pragma once

#include <string>
#include <vector>

#include "geometry/geometry.hpp"
#include "render/canvas.hpp"

namespace noneuclid::app {

struct UsageError {
    std::string message;
};
[[noreturn]] void usage_error(const std::string& message);

class Args {
public:
    // "--option=value" is read as "--option value" (a word that starts with "--" and holds "=").
    Args(int argc, char** argv, int first) : Args(std::vector<std::string>(argv + first, argv + argc)) {}
    explicit Args(std::vector<std::string> words);

    bool more() const { return at_ < words_.size(); }
    const std::string& next() { return words_[at_++]; }
    // Whether the word next() gave last was written after an "=" ("--option=value").
    bool last_attached() const { return at_ > 0 && attached_[at_ - 1]; }
    // The command whose --help an error points to ("render": "see 'noneuclid render --help'").
    void set_command(std::string name) { command_ = std::move(name); }
    std::string help_hint() const { return "see 'noneuclid " + (command_.empty() ? "" : command_ + " ") + "--help'"; }
    // The value after option `opt`.
    const std::string& value(const std::string& opt);
    // The value as a number in [lo, hi], a whole number in [lo, hi], WIDTHxHEIGHT.
    double number(const std::string& opt, double lo, double hi) { return parse_number(opt, value(opt), lo, hi); }
    long long count(const std::string& opt, long long lo, long long hi) { return parse_count(opt, value(opt), lo, hi); }

    // The same checks for a value found elsewhere (a recording's settings).
    static double parse_number(const std::string& opt, const std::string& text, double lo, double hi);
    static long long parse_count(const std::string& opt, const std::string& text, long long lo, long long hi);

private:
    std::vector<std::string> words_;
    std::vector<bool> attached_;  // words_[i] came after an "="
    std::size_t at_ = 0;
    std::string command_;
};

// Values that several commands take; each throws a UsageError naming `opt`.
void parse_size(const std::string& opt, const std::string& text, int& width, int& height);
geo::Projection parse_projection(const std::string& opt, const std::string& text);
render::PixelFormat parse_format(const std::string& opt, const std::string& text);
bool parse_on_off(const std::string& opt, const std::string& text);

}  // namespace noneuclid::app
