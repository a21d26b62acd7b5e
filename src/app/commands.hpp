// The commands of `noneuclid`, one file each (app/cmd_*.cpp): argv from `first` on are the
// command's options. Each returns the exit status; a bad option is a UsageError (exit 2).
// kCommands (app/commands.cpp) names them, says what each does, and is what main dispatches
// on and --help lists.
#pragma once

#include "app/options.hpp"

namespace noneuclid::app {

int run_command(int argc, char** argv, int first);
int render_command(int argc, char** argv, int first);
int dump_command(int argc, char** argv, int first);
int demo_command(int argc, char** argv, int first);
int accuracy_command(int argc, char** argv, int first);
int buttons_command(int argc, char** argv, int first);
int scores_command(int argc, char** argv, int first);
int scenes_command(int argc, char** argv, int first);
int measure_command(int argc, char** argv, int first);
int lesson_command(int argc, char** argv, int first);

struct CommandRow {
    Command command;
    const char* name;
    const char* summary;  // one line for --help
    const char* usage;    // what follows the command's name in its usage line
    int (*run)(int argc, char** argv, int first);
};
extern const CommandRow kCommands[kCommandCount];

// `noneuclid --help`: the commands, and where each one's options are; `noneuclid COMMAND
// --help`: that command's options.
void print_help();
void print_command_help(Command c);
const char* version();

}  // namespace noneuclid::app
