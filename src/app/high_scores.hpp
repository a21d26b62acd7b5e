// The game's high-score table, kept on disk for a kiosk that runs for months: the best ten
// games, one line each, in a text file a person can read:
//
//     # noneuclid high scores: score, level reached, when (UTC)
//     1230 3 2026-11-25T14:03:11Z
//
// Written whole or not at all (platform::AtomicFile: a temporary file beside it, flushed,
// fsync'd, renamed over it, the directory fsync'd), so a power cut or a crash mid-write leaves
// the old table or the new one, never a mix. Processes that share a table take turns (a lock on
// its directory, platform::DirectoryLock): each game over reads the table, adds its game and
// writes it back under the lock, so no game is lost. Only what the game wrote is ever touched:
// a regular file whose first line is the header above. Anything else at the path (a directory,
// a device, a symbolic link, another text) is refused and left alone, and nothing of it is
// shown. A table of the game's own that no longer reads as one (damaged by something else) is
// set aside by `run` as FILE.damaged (FILE.damaged.2, ... when there is one already) and a new
// table begun: the game goes on either way. `noneuclid scores` only reads. Where the file lives:
// `--scores FILE`, else the kiosk's state directory (platform::state_file).
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

// The table's text from its entries, and back; parse gives false with the line and its problem
// (each line's time must be written as the game writes it, YYYY-MM-DDTHH:MM:SSZ).
std::string format_scores(const std::vector<HighScore>& table);
bool parse_scores(const std::string& text, std::vector<HighScore>& out, std::string& why);
// Inserts a game in its place (after the equal scores before it); keeps the best kMaxScores.
void insert_score(std::vector<HighScore>& table, const HighScore& entry);
inline constexpr std::size_t kMaxScores = 10;

class HighScoreTable final : public GameOverSink {
public:
    explicit HighScoreTable(std::string path) : path_(std::move(path)) {}
    // Reads the table (missing or empty: an empty table). False with one sentence in `error`
    // when the path holds something that is not a table the game wrote, and, unless `repair`,
    // when the game's table is damaged. With `repair` (the game's own use) a damaged table is set
    // aside as above, with one line on stderr, and a new table begun.
    bool load(bool repair, std::string& error);
    long best() const { return table_.empty() ? 0 : table_.front().score; }
    const std::vector<HighScore>& entries() const { return table_; }
    const std::string& path() const { return path_; }
    // A game ended: into the table on the disk (save); an error is one line on stderr, and the
    // game is kept for the next save.
    void game_over(long score, int level) override;
    // Under the lock: the table read again, the games not saved yet added, the table written
    // whole. False with one sentence in `error`.
    bool save(std::string& error);

private:
    enum class Found { table, not_a_table, damaged };
    Found read(std::vector<HighScore>& table, std::string& why) const;
    bool set_aside(const std::string& why, std::string& error) const;

    std::string path_;
    std::vector<HighScore> table_;    // as last read or written
    std::vector<HighScore> pending_;  // games that ended and are not on the disk yet
};

}  // namespace noneuclid::app
