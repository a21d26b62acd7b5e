// `noneuclid scores`: the game's high-score table, best first (for a kiosk's keeper).
#include <cstdio>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "app/setup.hpp"

namespace noneuclid::app {

int scores_command(int argc, char** argv, int first) {
    Options o = defaults(Command::scores);
    Args args(argc, argv, first);
    parse_options(args, o, Command::scores);
    const std::string& choice = o.scores;
    if (choice == "none") usage_error("scores --scores none: name the table to print, or leave --scores out.");
    const std::unique_ptr<HighScoreTable> table = open_scores(choice, false);
    if (!table) return 1;
    if (table->entries().empty()) std::printf("no games yet\n");
    int rank = 0;
    for (const HighScore& e : table->entries())
        std::printf("%2d  %8ld  level %-3d  %s\n", ++rank, e.score, e.level, e.when.c_str());
    return 0;
}

}  // namespace noneuclid::app
