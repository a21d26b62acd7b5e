// The commands of `noneuclid`, one file each: argv from `first` on are the command's options.
// Each returns the exit status; a bad option is a UsageError (exit 2).
#pragma once

namespace noneuclid::app {

int accuracy_command(int argc, char** argv, int first);
int dump_command(int argc, char** argv, int first);
int render_command(int argc, char** argv, int first);
int demo_command(int argc, char** argv, int first);
int run_command(int argc, char** argv, int first);
int buttons_command(int argc, char** argv, int first);
int scores_command(int argc, char** argv, int first);
void print_help();
const char* version();

}  // namespace noneuclid::app
