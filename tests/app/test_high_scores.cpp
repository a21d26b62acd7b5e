// The high-score table (app/high_scores.hpp): its order and size, its file format, a damaged
// table set aside (never by the listing, never over an earlier one), what the game did not write
// left alone and unshown, processes sharing a table keeping every game, and a writer killed
// (SIGKILL) at random moments, again and again: the file is always a whole table, the one before
// or the one after, and the next write clears what the killed one left.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

#include "app/high_scores.hpp"
#include "world/quote.hpp"

using namespace noneuclid;
namespace fs = std::filesystem;

namespace {

// A directory of this test's own (ctest runs the tests in parallel processes).
fs::path temp_dir() {
    const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
    fs::path d = fs::path(::testing::TempDir()) / (std::string(t->test_suite_name()) + "." + t->name());
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}
std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST(HighScores, BestFirstTenKeptEqualScoresInArrivalOrder) {
    std::vector<app::HighScore> t;
    for (long s : {50, 10, 90, 50, 30, 70, 20, 80, 60, 40, 100, 5}) app::insert_score(t, {s, 1, "t" + std::to_string(s)});
    ASSERT_EQ(t.size(), app::kMaxScores);
    const long expect[] = {100, 90, 80, 70, 60, 50, 50, 40, 30, 20};
    for (std::size_t i = 0; i < t.size(); ++i) EXPECT_EQ(t[i].score, expect[i]) << i;
    app::insert_score(t, {1, 1, "low"});  // below the tenth: not kept
    EXPECT_EQ(t.back().score, 20);
}

TEST(HighScores, FileFormatRoundTripsAndRefusesWhatIsNotATable) {
    std::vector<app::HighScore> t = {{1230, 3, "2026-11-25T14:03:11Z"}, {400, 1, "2026-11-24T09:00:00Z"}};
    const std::string text = app::format_scores(t);
    EXPECT_EQ(text, "# noneuclid high scores: score, level reached, when (UTC)\n1230 3 2026-11-25T14:03:11Z\n"
                    "400 1 2026-11-24T09:00:00Z\n");
    std::vector<app::HighScore> back;
    std::string why;
    ASSERT_TRUE(app::parse_scores(text, back, why)) << why;
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].score, 1230);
    EXPECT_EQ(back[1].when, "2026-11-24T09:00:00Z");
    for (const char* bad : {"1230 3 2026\n400", "12x0 3 now\n", "100 1 a\n200 1 b\n", "100 0 a\n", "-5 1 a\n",
                            "100 1 a extra\n", "\x01\x02\x03\n"}) {
        EXPECT_FALSE(app::parse_scores(bad, back, why)) << bad;
        EXPECT_FALSE(why.empty());
    }
}

constexpr const char* kHeaderLine = "# noneuclid high scores: score, level reached, when (UTC)\n";

// Loads the table at `file` as `run` does (repair) or as `scores` does; what it said on stderr.
bool load(app::HighScoreTable& t, bool repair, std::string& error, std::string& said) {
    testing::internal::CaptureStderr();
    const bool ok = t.load(repair, error);
    said = testing::internal::GetCapturedStderr();
    return ok;
}

TEST(HighScores, ADamagedTableOfTheGamesIsSetAsideWithoutReplacingAnEarlierOne) {
    const fs::path dir = temp_dir(), file = dir / "scores";
    const std::string first = std::string(kHeaderLine) + "1200 2 yesterday\n\xff\xfe garbage\n";
    std::ofstream(file) << first;
    app::HighScoreTable t(file.string());
    std::string error, said;
    ASSERT_TRUE(load(t, true, error, said)) << error;
    EXPECT_NE(said.find("is damaged"), std::string::npos) << said;
    EXPECT_NE(said.find("set aside as"), std::string::npos) << said;
    EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << "one line";
    EXPECT_TRUE(t.entries().empty());
    EXPECT_EQ(read(dir / "scores.damaged"), first);
    EXPECT_FALSE(fs::exists(file));
    t.game_over(700, 2);
    app::HighScoreTable again(file.string());
    ASSERT_TRUE(again.load(true, error)) << error;
    ASSERT_EQ(again.entries().size(), 1u);
    EXPECT_EQ(again.best(), 700);

    // A second damaged table: beside the first, which stays as it was.
    const std::string second = std::string(kHeaderLine) + "90 1 2026-11-25T14:03:11Z\n95 1 2026-11-25T14:03:12Z\n";
    std::ofstream(file) << second;
    app::HighScoreTable third(file.string());
    ASSERT_TRUE(load(third, true, error, said)) << error;
    EXPECT_NE(said.find("scores.damaged.2"), std::string::npos) << said;
    EXPECT_EQ(read(dir / "scores.damaged"), first);
    EXPECT_EQ(read(dir / "scores.damaged.2"), second);
}

// `noneuclid scores` only reads: a damaged table is said to be damaged and left where it is.
TEST(HighScores, ReadingOnlyNeverSetsADamagedTableAside) {
    const fs::path dir = temp_dir(), file = dir / "scores";
    const std::string text = std::string(kHeaderLine) + "1200 2 2026-11-25T14:03:11Z\nhalf a li";
    std::ofstream(file) << text;
    app::HighScoreTable t(file.string());
    std::string error, said;
    EXPECT_FALSE(load(t, false, error, said));
    EXPECT_NE(error.find("is damaged (line 3 is not a score"), std::string::npos) << error;
    EXPECT_EQ(said, "");
    EXPECT_EQ(read(file), text);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "nothing made beside it";
}

// Whatever the game did not write (by its first line, or by not being a regular file) is
// refused by both `run` and `scores`, left exactly as it was, and nothing of it is shown.
TEST(HighScores, WhatTheGameDidNotWriteIsLeftAloneAndNotShown) {
    const fs::path dir = temp_dir();
    std::ofstream(dir / "notes.txt") << "SECRET notes\n1200 2 2026-11-25T14:03:11Z\n";
    std::ofstream(dir / "target") << "# noneuclid high scores\nSECRET 1 2\n";
    fs::create_symlink(dir / "target", dir / "link");
    fs::create_symlink(dir / "nowhere", dir / "dangling");
    fs::create_directory(dir / "dir");
    ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
    const struct {
        const char* name;
        const char* says;
    } cases[] = {
        {"notes.txt", "it is not a high-score table the game wrote"},
        {"link", "it is a symbolic link, not a regular file"},
        {"dangling", "it is a symbolic link, not a regular file"},
        {"dir", "it is a directory, not a regular file"},
        {"fifo", "it is a pipe (FIFO), not a regular file"},
    };
    for (const auto& c : cases) {
        for (const bool repair : {true, false}) {
            const fs::path file = dir / c.name;
            const auto before = fs::symlink_status(file).type();
            app::HighScoreTable t(file.string());
            std::string error, said;
            EXPECT_FALSE(load(t, repair, error, said)) << c.name;
            EXPECT_NE(error.find(c.says), std::string::npos) << error;
            EXPECT_NE(error.find("it is left alone"), std::string::npos) << error;
            EXPECT_EQ((error + said).find("SECRET"), std::string::npos) << error + said;
            EXPECT_EQ(fs::symlink_status(file).type(), before) << c.name;
            // A game over on such a path does not write it either.
            testing::internal::CaptureStderr();
            t.game_over(10, 1);
            said = testing::internal::GetCapturedStderr();
            EXPECT_NE(said.find("the game is not saved"), std::string::npos) << said;
            EXPECT_EQ(fs::symlink_status(file).type(), before) << c.name;
        }
    }
    EXPECT_EQ(read(dir / "notes.txt"), "SECRET notes\n1200 2 2026-11-25T14:03:11Z\n");
    EXPECT_EQ(read(dir / "target"), "# noneuclid high scores\nSECRET 1 2\n");
    for (const auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find("damaged"), std::string::npos) << e.path();
}

// A table's times are the game's own shape; anything else (a control character, an escape
// sequence) is damage, shown escaped in the sentence and never printed as it is.
TEST(HighScores, ControlCharactersInATableAreNeverPassedOn) {
    std::vector<app::HighScore> t;
    std::string why;
    for (const std::string bad : {"100 1 \x1b[2J\n", "100 1 2026-11-25T14:03:11Z\x07\n", "100 1 2026-11-25 14:03:11\n",
                                  "100 1 2026-11-25T14:03:1Z\n"}) {
        EXPECT_FALSE(app::parse_scores(bad, t, why)) << bad;
        EXPECT_TRUE(world::is_plain(why)) << why;
    }
    ASSERT_TRUE(app::parse_scores("100 1 2026-11-25T14:03:11Z\n", t, why)) << why;
    EXPECT_TRUE(world::is_plain(t.at(0).when));
}

// Four processes share one table and end five games each, all at once (they start together,
// released by one closed pipe), 20 times: every game is kept, and the table is the best ten of
// the twenty, as one process ending them all would have it (each game over locks, reads, merges
// and writes). Without the lock and the read under it, a process writes its own view over the
// others' games.
TEST(HighScores, ProcessesSharingATableKeepEveryGame) {
    const fs::path dir = temp_dir(), file = dir / "scores";
    constexpr int kProcesses = 4, kGames = 5;
    std::vector<app::HighScore> expect;
    for (int p = 0; p < kProcesses; ++p)
        for (int g = 0; g < kGames; ++g) app::insert_score(expect, {1000L * (p + 1) + g, 1, ""});
    for (int round = 0; round < 20; ++round) {
        fs::remove(file);
        int go[2];
        ASSERT_EQ(pipe(go), 0);
        std::vector<pid_t> players;
        for (int p = 0; p < kProcesses; ++p) {
            const pid_t child = fork();
            ASSERT_GE(child, 0);
            if (child == 0) {  // a player: never returns
                close(go[1]);
                char c;
                if (read(go[0], &c, 1) != 0) _exit(3);  // until the parent closes its end
                app::HighScoreTable t(file.string());
                std::string error;
                if (!t.load(true, error)) _exit(2);
                for (int g = 0; g < kGames; ++g) t.game_over(1000L * (p + 1) + g, 1);
                _exit(0);
            }
            players.push_back(child);
        }
        close(go[0]);
        close(go[1]);  // all start now
        for (const pid_t child : players) {
            int status = 0;
            waitpid(child, &status, 0);
            ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "round " << round;
        }
        std::vector<app::HighScore> t;
        std::string why;
        ASSERT_TRUE(app::parse_scores(read(file), t, why)) << "round " << round << ": " << why;
        ASSERT_EQ(t.size(), expect.size()) << "round " << round << ": games were lost";
        for (std::size_t i = 0; i < t.size(); ++i) EXPECT_EQ(t[i].score, expect[i].score) << "round " << round << ", " << i;
    }
}

// A child writes the table over and over, each time one game more, and tells the parent through a
// pipe when each write is whole; the parent waits for the first (however slow the disk), then
// kills it with SIGKILL after a random few milliseconds, 150 times. After each kill the file must
// read as a whole table, the last one the child finished or the one it was writing. Kills that
// landed mid-write show as the hidden temporary file they leave (AtomicFile's), and some must;
// the next writer's first write clears it, so there is never more than the last kill's.
TEST(HighScores, AWriterKilledMidWriteNeverLeavesAHalfTable) {
    const fs::path dir = temp_dir(), file = dir / "scores";
    std::mt19937 g(11);
    std::uniform_int_distribution<int> pause_us(200, 6000);
    long round_best = 0;
    int left_by_kills = 0;
    for (int round = 0; round < 150; ++round) {
        int done[2];
        ASSERT_EQ(pipe(done), 0);
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {  // the writer: never returns
            close(done[0]);
            app::HighScoreTable t(file.string());
            std::string error;
            if (!t.load(true, error)) _exit(2);
            for (long s = t.best() + 1;; ++s) {
                t.game_over(s, 1);
                if (write(done[1], "w", 1) != 1) _exit(1);
            }
        }
        close(done[1]);
        pollfd first{done[0], POLLIN, 0};
        ASSERT_EQ(poll(&first, 1, 60000), 1) << "round " << round << ": the writer finished no write in 60 s";
        std::this_thread::sleep_for(std::chrono::microseconds(pause_us(g)));
        kill(child, SIGKILL);
        int status = 0;
        waitpid(child, &status, 0);
        close(done[0]);
        ASSERT_TRUE(WIFSIGNALED(status)) << "round " << round << ": the writer stopped by itself";
        std::vector<app::HighScore> t;
        std::string why;
        ASSERT_TRUE(app::parse_scores(read(file), t, why)) << "round " << round << ": " << why;
        ASSERT_FALSE(t.empty());
        EXPECT_GT(t.front().score, round_best) << "each round adds a game at least";
        round_best = t.front().score;
        int leftovers = 0;
        for (const auto& e : fs::directory_iterator(dir))
            leftovers += e.path().filename().string().rfind(".scores.noneuclid-", 0) == 0;
        EXPECT_LE(leftovers, 1) << "round " << round << ": an earlier kill's temporary file was not cleared";
        left_by_kills += leftovers;
    }
    EXPECT_GT(round_best, 0);
    EXPECT_GT(left_by_kills, 0) << "no kill landed mid-write: the test proved nothing";
    EXPECT_FALSE(fs::exists(dir / "scores.damaged"));
}
