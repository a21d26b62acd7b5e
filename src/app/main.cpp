// noneuclid: the command line. Each command lives in a file of its own (app/cmd_*.cpp, named in
// app/commands.cpp's table); options with no command are run's. A bad word anywhere is one
// sentence on stderr and exit status 2.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>
#include <system_error>

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
    } catch (const std::bad_alloc&) {
        // Everything is sized before the run starts (the canvas, the GIF's buffers, the frame's
        // scratch, the scene and its images), so this is a request too large for the memory the
        // process may have. The unwinding has removed any temporary file; what was there is
        // left as it was.
        std::fprintf(stderr,
                     "noneuclid: out of memory: %s needs more memory than this process may have (the canvas "
                     "takes 4 bytes a pixel, a GIF 4 more): use a smaller --size or a smaller scene; no file was "
                     "written or changed.\n",
                     argc > 1 && argv[1][0] != '-' ? argv[1] : "the run");
        return 2;
    } catch (const std::system_error& e) {
        // A worker thread that cannot start (its stack is memory too); the same unwinding.
        std::fprintf(stderr,
                     "noneuclid: cannot start a thread (%s): use fewer --threads, or give the process more memory; no "
                     "file was written or changed.\n",
                     e.code().message().c_str());
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
