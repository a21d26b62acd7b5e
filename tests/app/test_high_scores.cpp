// The high-score table (app/high_scores.hpp): its order and size, its file format, a damaged
// file set aside, and a writer killed (SIGKILL) at random moments, again and again: the file is
// always a whole table, the one before or the one after.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "app/high_scores.hpp"

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

TEST(HighScores, ADamagedFileIsSetAsideAndANewTableBegun) {
    const fs::path dir = temp_dir(), file = dir / "scores";
    std::ofstream(file) << "# noneuclid high scores\n1200 2 yesterday\n\xff\xfe garbage\n";
    testing::internal::CaptureStderr();
    app::HighScoreTable t(file.string());
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_NE(said.find("is damaged"), std::string::npos) << said;
    EXPECT_NE(said.find("set aside as"), std::string::npos) << said;
    EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << "one line";
    EXPECT_TRUE(t.entries().empty());
    EXPECT_TRUE(fs::exists(dir / "scores.damaged"));
    EXPECT_FALSE(fs::exists(file));
    t.game_over(700, 2);
    app::HighScoreTable again(file.string());
    ASSERT_EQ(again.entries().size(), 1u);
    EXPECT_EQ(again.best(), 700);
}

// A child writes the table over and over, each time one game more, and tells the parent through a
// pipe when each write is whole; the parent waits for the first (however slow the disk), then
// kills it with SIGKILL after a random few milliseconds, 150 times. After each kill the file must
// read as a whole table, the last one the child finished or the one it was writing. Kills that
// landed mid-write show as the hidden temporary files they leave (AtomicFile's), and some must.
TEST(HighScores, AWriterKilledMidWriteNeverLeavesAHalfTable) {
    const fs::path dir = temp_dir(), file = dir / "scores";
    std::mt19937 g(11);
    std::uniform_int_distribution<int> pause_us(200, 6000);
    long round_best = 0;
    for (int round = 0; round < 150; ++round) {
        int done[2];
        ASSERT_EQ(pipe(done), 0);
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {  // the writer: never returns
            close(done[0]);
            app::HighScoreTable t(file.string());
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
    }
    EXPECT_GT(round_best, 0);
    int leftovers = 0;
    for (const auto& e : fs::directory_iterator(dir)) leftovers += e.path().filename().string().rfind(".scores.", 0) == 0;
    EXPECT_GT(leftovers, 0) << "no kill landed mid-write: the test proved nothing";
    EXPECT_FALSE(fs::exists(dir / "scores.damaged"));
}
