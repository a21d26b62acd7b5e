// Each command's --help and what it reads are the same options: every option some command
// has, tried on every command, is read there exactly when that command's --help lists it (the
// help, app/help.cpp, lists options_help; parse_option reads the command line).
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "app/args.hpp"
#include "app/options.hpp"

namespace {

using namespace noneuclid;

std::string option_name(const std::string& head) { return head.substr(0, head.find(' ')); }

TEST(Options, EachCommandReadsExactlyTheOptionsItsHelpLists) {
    std::set<std::string> every;
    std::vector<std::set<std::string>> listed(app::kCommandCount);
    for (int c = 0; c < app::kCommandCount; ++c)
        for (const app::OptionHelp& h : app::options_help(static_cast<app::Command>(c))) {
            listed[c].insert(option_name(h.head));
            every.insert(option_name(h.head));
        }
    ASSERT_GT(every.size(), 40u);
    for (int c = 0; c < app::kCommandCount; ++c) {
        const app::Command command = static_cast<app::Command>(c);
        for (const std::string& name : every) {
            app::Options o;
            app::Args args(std::vector<std::string>{"0"});  // a value for an option that takes one
            bool read = false;
            try {
                read = app::parse_option(args, name, o, command);
            } catch (const app::UsageError&) {
                read = true;  // read, and its value refused: still the command's option
            }
            EXPECT_EQ(read, listed[c].count(name) == 1)
                << app::command_name(command) << " " << name << (read ? ": read, not in its --help" : ": in its --help, not read");
        }
    }
}

// An option read its own way by a command has that command's words in its help: measure's
// --curvature and --centre are the instrument's, not the world's.
TEST(Options, MeasureDescribesItsOwnCurvatureAndCentre) {
    for (const app::OptionHelp& h : app::options_help(app::Command::measure)) {
        if (option_name(h.head) == "--curvature" || option_name(h.head) == "--centre") {
            EXPECT_EQ(h.help.find("the world starts"), std::string::npos) << h.help;
            EXPECT_EQ(h.help.find("earth"), std::string::npos) << h.help;
        }
    }
}

}  // namespace
