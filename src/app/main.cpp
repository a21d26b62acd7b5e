// noneuclid: the command line. Each command lives in a file of its own (app/cmd_*.cpp); a bad
// word anywhere is one sentence on stderr and exit status 2.
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
    for (int i = 1; i < argc; ++i) {  // help wins wherever it is
        if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0) {
            print_help();
            return 0;
        }
    }
    if (word == "--version") {
        if (argc > 2) usage_error("--version takes nothing after it, not '" + std::string(argv[2]) + "'.");
        std::printf("noneuclid %s\n", version());
        return 0;
    }
    if (word == "run") return run_command(argc, argv, 2);
    if (word == "render") return render_command(argc, argv, 2);
    if (word == "dump") return dump_command(argc, argv, 2);
    if (word == "demo") return demo_command(argc, argv, 2);
    if (word == "accuracy") return accuracy_command(argc, argv, 2);
    if (word == "buttons") return buttons_command(argc, argv, 2);
    if (word == "scores") return scores_command(argc, argv, 2);
    if (word[0] == '-') return accuracy_command(argc, argv, 1);  // `noneuclid --samples N`, as before
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
