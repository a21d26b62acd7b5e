// noneuclid: the command line. Each command lives in a file of its own (app/cmd_*.cpp, named in
// app/commands.cpp's table); options with no command are run's. A bad word anywhere is one
// sentence on stderr and exit status 2.
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "app/platform.hpp"

namespace {

int dispatch(int argc, char** argv) {
    using namespace noneuclid::app;
    if (argc == 1) return demo_command(argc, argv, 1);
    const std::string word = argv[1];
    Command command = Command::run;
    const bool named = parse_command(word, command);
    for (int i = 1; i < argc; ++i) {  // help wins wherever it is
        if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0) {
            if (named) print_command_help(command);
            else print_help();
            return 0;
        }
    }
    if (word == "--version") {
        if (argc > 2) usage_error("--version takes nothing after it, not '" + std::string(argv[2]) + "'.");
        std::printf("noneuclid %s\n", version());
        return 0;
    }
    if (named) return kCommands[static_cast<int>(command)].run(argc, argv, 2);
    if (word[0] == '-') return run_command(argc, argv, 1);  // `noneuclid --scene asteroids`: run's options
    usage_error("unknown command '" + word + "'; see 'noneuclid --help'.");
}

}  // namespace

int main(int argc, char** argv) {
    noneuclid::platform::prepare_process();
    int status = 0;
    try {
        status = dispatch(argc, argv);
    } catch (const noneuclid::app::UsageError& e) {
        std::fprintf(stderr, "noneuclid: %s\n", e.message.c_str());
        return 2;
    }
    // What went to standard output (a report, help, a dump) must have arrived: a full disk or a
    // closed pipe is one sentence and a non-zero exit, not a silent success.
    if ((std::fflush(stdout) != 0 || std::ferror(stdout)) && status == 0) {
        std::fprintf(stderr, "noneuclid: cannot write to standard output (%s): check where it goes.\n",
                     std::strerror(errno));
        return 1;
    }
    return status;
}
