// The game's high-score table, kept on disk for a kiosk that runs for months: the best ten
// games, one line each, in a text file a person can read:
//
//     # noneuclid high scores: score, level reached, when (UTC)
//     1230 3 2026-11-25T14:03:11Z
//
// Written whole or not at all (platform::AtomicFile: a temporary file beside it, flushed,
// fsync'd, renamed over it, the directory fsync'd), so a power cut or a crash mid-write leaves
// the old table or the new one, never a mix. A file that cannot be read as a table (damaged by
// something else) is reported in one line, renamed to FILE.damaged, and a new table begun: the
// game goes on either way. Where the file lives: `run --scores FILE`, else the kiosk's state
// directory (platform::state_file).
#pragma once

#include <string>
#include <vector>

#include "app/session.hpp"

namespace noneuclid::app {

struct HighScore {
    long score = 0;
    int level = 1;
    std::string when;  // ISO 8601, UTC
};

// The table's text from its entries, and back; parse gives false with the line and its problem.
std::string format_scores(const std::vector<HighScore>& table);
bool parse_scores(const std::string& text, std::vector<HighScore>& out, std::string& why);
// Inserts a game in its place (after the equal scores before it); keeps the best kMaxScores.
void insert_score(std::vector<HighScore>& table, const HighScore& entry);
inline constexpr std::size_t kMaxScores = 10;

class HighScoreTable final : public GameOverSink {
public:
    // Reads `path` (missing: an empty table). A damaged file is set aside, as above, with one
    // line on stderr. Never fails: the worst case is an empty table that is not saved.
    explicit HighScoreTable(std::string path);
    long best() const { return table_.empty() ? 0 : table_.front().score; }
    const std::vector<HighScore>& entries() const { return table_; }
    const std::string& path() const { return path_; }
    // A game ended: into the table and onto the disk (a write error is one line on stderr).
    void game_over(long score, int level) override;
    // The table onto the disk, whole or not at all; false with one sentence in `error`.
    bool save(std::string& error) const;

private:
    std::string path_;
    std::vector<HighScore> table_;
};

}  // namespace noneuclid::app
