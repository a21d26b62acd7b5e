#include "app/high_scores.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <sstream>
#include <string_view>

#include "app/platform.hpp"
#include "world/quote.hpp"

namespace noneuclid::app {

namespace {
constexpr const char* kHeader = "# noneuclid high scores: score, level reached, when (UTC)\n";
// What makes a file the game's table: its first line begins with the header's words.
constexpr std::string_view kSignature = "# noneuclid high scores";
constexpr std::size_t kScoresFileLimit = 64 << 10;

// A time as now_utc writes it: 2026-11-25T14:03:11Z.
bool is_utc_time(const std::string& s) {
    constexpr std::string_view kShape = "dddd-dd-ddTdd:dd:ddZ";
    if (s.size() != kShape.size()) return false;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (kShape[i] == 'd' ? s[i] < '0' || s[i] > '9' : s[i] != kShape[i]) return false;
    return true;
}

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
        if (!(words >> e.score >> e.level >> e.when) || (words >> extra) || e.score < 0 || e.level < 1 || !is_utc_time(e.when) ||
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

HighScoreTable::Found HighScoreTable::read(std::vector<HighScore>& table, std::string& why) const {
    table.clear();
    std::string text;
    platform::FileKind kind{};
    if (!platform::read_kept_file(path_, kScoresFileLimit, text, kind, why)) return Found::not_a_table;
    if (text.empty()) return Found::table;  // missing, or emptied: nothing to lose
    // Nothing of a file that is not the game's is shown: it may be anything the path reaches.
    if (text.compare(0, kSignature.size(), kSignature) != 0) {
        why = "it is not a high-score table the game wrote (its first line is not the table's header)";
        return Found::not_a_table;
    }
    if (text.size() > kScoresFileLimit) {
        why = "it is over the 64 KiB a table may have";
        return Found::damaged;
    }
    return parse_scores(text, table, why) ? Found::table : Found::damaged;
}

bool HighScoreTable::set_aside(const std::string& why, std::string& error) const {
    std::string aside, failed;
    if (!platform::set_aside(path_, ".damaged", aside, failed)) {
        error = "the high-score table " + world::quote(path_, world::kPathLimit) + " is damaged (" + why + ") and " + failed + ".";
        return false;
    }
    std::fprintf(stderr, "noneuclid: the high-score table %s is damaged (%s): it is set aside as %s, and a new table begun.\n",
                 world::quote(path_, world::kPathLimit).c_str(), why.c_str(), world::quote(aside, world::kPathLimit).c_str());
    return true;
}

bool HighScoreTable::load(bool repair, std::string& error) {
    std::string why;
    switch (read(table_, why)) {
        case Found::table: return true;
        case Found::not_a_table:
            error = "the high-score table " + world::quote(path_, world::kPathLimit) + ": " + why +
                    ": it is left alone; give --scores the path of a table (or none).";
            return false;
        case Found::damaged: break;
    }
    table_.clear();
    if (repair) return set_aside(why, error);
    error = "the high-score table " + world::quote(path_, world::kPathLimit) + " is damaged (" + why +
            "): it is left as it is; 'noneuclid run' sets it aside and begins a new one.";
    return false;
}

void HighScoreTable::game_over(long score, int level) {
    const HighScore game{score, level, now_utc()};
    pending_.push_back(game);
    std::string error;
    if (save(error)) return;
    insert_score(table_, game);  // shown as played; written with the next save that can be
    std::fprintf(stderr, "noneuclid: the high-score table: %s\n", error.c_str());
}

bool HighScoreTable::save(std::string& error) {
    const platform::DirectoryLock lock(path_);
    if (lock.busy()) {
        error = "cannot save " + world::quote(path_, world::kPathLimit) +
                ": another process has held its directory's lock for over five seconds; the game is saved with the next.";
        return false;
    }
    std::vector<HighScore> table;
    std::string why;
    switch (read(table, why)) {
        case Found::table: break;
        case Found::not_a_table:
            error = "cannot save " + world::quote(path_, world::kPathLimit) + ": " + why + ": it is left alone, and the game is not saved.";
            return false;
        case Found::damaged:
            if (!set_aside(why, error)) return false;
            table.clear();
            break;
    }
    for (const HighScore& game : pending_) insert_score(table, game);
    platform::AtomicFile f;
    if (!f.open(path_, error)) return false;
    const std::string text = format_scores(table);
    if (std::fwrite(text.data(), 1, text.size(), f.file()) != text.size()) {
        error = "cannot write " + path_ + " (check the disk has room); it is left as it was.";
        return false;
    }
    if (!f.commit(error)) return false;
    pending_.clear();
    table_ = std::move(table);
    return true;
}

}  // namespace noneuclid::app
