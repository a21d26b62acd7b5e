#include "app/high_scores.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "app/platform.hpp"
#include "world/quote.hpp"
#include "files/text_file.hpp"

namespace noneuclid::app {

namespace {
constexpr const char* kHeader = "# noneuclid high scores: score, level reached, when (UTC)\n";
constexpr std::size_t kScoresFileLimit = 64 << 10;

std::string now_utc() {
    const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm tm{};
    if (const std::tm* g = std::gmtime(&t)) tm = *g;  // (called on the frame loop's thread only)
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}
}  // namespace

std::string format_scores(const std::vector<HighScore>& table) {
    std::string out = kHeader;
    for (const HighScore& e : table) out += std::to_string(e.score) + ' ' + std::to_string(e.level) + ' ' + e.when + '\n';
    return out;
}

bool parse_scores(const std::string& text, std::vector<HighScore>& out, std::string& why) {
    out.clear();
    std::istringstream in(text);
    std::string line;
    long number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        HighScore e;
        std::string extra;
        if (!(words >> e.score >> e.level >> e.when) || (words >> extra) || e.score < 0 || e.level < 1 ||
            out.size() >= kMaxScores || (!out.empty() && e.score > out.back().score)) {
            why = "line " + std::to_string(number) + " is not a score, a level and a time below the one before: " +
                  world::quote(line);
            return false;
        }
        out.push_back(e);
    }
    if (!text.empty() && text.back() != '\n') {  // a file cut short
        why = "its last line is cut short";
        return false;
    }
    return true;
}

void insert_score(std::vector<HighScore>& table, const HighScore& entry) {
    std::size_t i = 0;
    while (i < table.size() && table[i].score >= entry.score) ++i;
    if (i >= kMaxScores) return;
    table.insert(table.begin() + static_cast<std::ptrdiff_t>(i), entry);
    if (table.size() > kMaxScores) table.resize(kMaxScores);
}

HighScoreTable::HighScoreTable(std::string path) : path_(std::move(path)) {
    std::error_code ec;
    if (!std::filesystem::exists(path_, ec)) return;
    std::string text, why;
    if (files::read_text_file(path_, kScoresFileLimit, "a high-score table", text, why) && parse_scores(text, table_, why))
        return;
    table_.clear();
    const std::string aside = path_ + ".damaged";
    std::filesystem::rename(path_, aside, ec);
    std::fprintf(stderr, "noneuclid: the high-score table %s is damaged (%s): %s, and a new table begun.\n",
                 world::quote(path_).c_str(), why.c_str(),
                 ec ? ("it could not be set aside (" + ec.message() + ")").c_str()
                    : ("it is set aside as " + world::quote(aside)).c_str());
}

void HighScoreTable::game_over(long score, int level) {
    insert_score(table_, {score, level, now_utc()});
    std::string error;
    if (!save(error)) std::fprintf(stderr, "noneuclid: the high-score table: %s\n", error.c_str());
}

bool HighScoreTable::save(std::string& error) const {
    platform::AtomicFile f;
    if (!f.open(path_, error)) return false;
    const std::string text = format_scores(table_);
    if (std::fwrite(text.data(), 1, text.size(), f.file()) != text.size()) {
        error = "cannot write " + path_ + " (check the disk has room); it is left as it was.";
        return false;
    }
    return f.commit(error);
}

}  // namespace noneuclid::app
