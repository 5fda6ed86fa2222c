// `locus view [EQUATION | SCENE.toml | FILE.param]`: serves the interactive page of view/ on
// 127.0.0.1 (or --host) and prints `serving on http://HOST:PORT/` as its first line. Ctrl-C
// (SIGINT) or SIGTERM stops it cleanly; --timeout stops it after that many seconds (exit 0:
// serving for a while is the job) and bounds the start-up (implicitizing a .param file).
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <thread>

#include "algebra/error.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/process_limits.h"
#include "cli/surface_input.h"
#include "render/framing.h"
#include "view/frame_builder.h"
#include "view/view_server.h"

namespace locus::cli {
namespace {

struct ViewArgs {
    std::string input;
    std::string host = "127.0.0.1";
    int port = 8765;
    bool open = false;
    int threads = 0;
    std::optional<double> timeout;
};

// The pipe through which SIGINT and SIGTERM reach the thread that stops the server: the
// handler writes a byte (write is async-signal-safe), that thread reads it.
int stop_pipe[2] = {-1, -1};

extern "C" void request_stop(int) {
    const char byte = 0;
    [[maybe_unused]] const ssize_t written = ::write(stop_pipe[1], &byte, 1);
}

// The scene the command line names, compiled and framed once.
view::Startup startup_of(const std::string& input, Deadline deadline) {
    view::Startup startup;
    const SourceKind kind = source_kind(input);
    startup.label = input;
    if (kind == SourceKind::equation) {
        // The page renders equations itself (names other than x, y, z become its sliders);
        // a malformed one is an error here, at its column.
        try {
            view::equation_parameters(input);
        } catch (const Error& e) {
            throw failure_about("equation", e);
        }
        startup.equation = input;
        return startup;
    }
    try {
        startup.scene = scene_from_source(input, kind, std::nullopt, deadline);
        startup.compiled = compile_surfaces(startup.scene, deadline);
        render::fit_clip_regions(startup.scene, startup.compiled, false, deadline);
    } catch (const Timeout& e) {
        throw CommandFailure(exit_timeout, std::string(e.what()) + " (--timeout)");
    } catch (const Error& e) {
        throw failure_about(input, e);
    }
    if (startup.scene.surfaces.size() == 1 && startup.scene.objects.empty() &&
        startup.scene.surfaces[0].trim == nullptr) {
        // A parametrization: the page shows (and lets the user edit) its implicit equation.
        startup.equation = startup.compiled[0].equation();
    }
    return startup;
}

void open_browser(const std::string& url) {
    const std::string command = "xdg-open '" + url + "' >/dev/null 2>&1 &";
    if (std::system(command.c_str()) != 0) {
        std::fprintf(stderr, "locus: --open: could not start a browser; open %s\n", url.c_str());
    }
}

int run_view(const ViewArgs& args) {
    if (args.port < 0 || args.port > 65535) {
        throw CommandFailure(exit_input, "--port " + std::to_string(args.port) +
                                             ": expected 0 (any free port) to 65535");
    }
    if (args.timeout && !(*args.timeout > 0.0)) {
        throw CommandFailure(exit_input, "--timeout: expected a positive number of seconds");
    }
    const auto started = std::chrono::steady_clock::now();
    const auto until =
        args.timeout
            ? std::optional(started +
                            std::chrono::duration_cast<std::chrono::nanoseconds>(
                                std::chrono::duration<double>(std::min(*args.timeout, 3.15e7))))
            : std::nullopt;
    view::ViewOptions options;
    options.host = args.host;
    options.port = args.port;
    options.render_threads = args.threads;
    if (!args.input.empty()) {
        options.startup = startup_of(args.input, until);
    }
    if (args.host != "127.0.0.1" && args.host != "localhost" && args.host != "::1") {
        std::fprintf(stderr,
                     "locus: warning: --host %s: the page is served beyond this machine; anyone "
                     "who reaches the address can render with it\n",
                     args.host.c_str());
    }
    // SIGINT and SIGTERM go to one thread that stops the server: every thread started from
    // here on (httplib's, oneTBB's) inherits a mask that blocks them, that thread unblocks them,
    // and their handler writes to the pipe it reads. A handler rather than sigwait: threads that
    // libraries start before main (OpenBLAS's, which the sanitized build links in through
    // OpenImageIO) do not block them, and the signal's default action there ended the process.
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    if (::pipe2(stop_pipe, O_CLOEXEC) != 0) {
        throw CommandFailure(exit_resource, "cannot make a pipe for the stop signals");
    }
    struct sigaction action = {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);

    view::ViewServer server(std::move(options));
    int port = 0;
    try {
        port = server.bind();
    } catch (const Error& e) {
        throw CommandFailure(exit_input, std::string("--host/--port: ") + e.what());
    }
    const std::string url =
        "http://" + (args.host.find(':') != std::string::npos ? "[" + args.host + "]" : args.host) +
        ":" + std::to_string(port) + "/";
    std::cout << "serving on " << url << std::endl;
    if (args.open) {
        open_browser(url);
    }
    std::mutex mutex;
    std::condition_variable stopped_cv;
    bool stopped = false;
    std::thread signal_waiter([&] {
        pthread_sigmask(SIG_UNBLOCK, &signals, nullptr);
        char byte = 0;
        while (::read(stop_pipe[0], &byte, 1) < 0 && errno == EINTR) {
        }
        server.stop();
    });
    std::thread timer;
    if (until) {
        timer = std::thread([&] {
            std::unique_lock<std::mutex> lock(mutex);
            if (!stopped_cv.wait_until(lock, *until, [&] { return stopped; })) {
                server.stop();
            }
        });
    }
    server.run();
    {
        const std::lock_guard<std::mutex> lock(mutex);
        stopped = true;
    }
    stopped_cv.notify_all();
    if (timer.joinable()) {
        timer.join();
    }
    // Wake the signal thread if the server stopped for another reason.
    request_stop(0);
    signal_waiter.join();
    std::fprintf(stderr, "locus view: stopped\n");
    return exit_ok;
}

}  // namespace

void add_view_command(CLI::App& app, CommandContext& context) {
    auto args = std::make_shared<ViewArgs>();
    CLI::App* cmd = app.add_subcommand(
        "view", "Explore a surface interactively in the browser (a local web server)");
    cmd->add_option("input", args->input,
                    "an equation, a scene file (.toml) or a parametrization (.param, .bpt); "
                    "without one the page starts with an example");
    cmd->add_option("--host", args->host, "the address to serve on (default 127.0.0.1)");
    cmd->add_option("--port", args->port, "the port (default 8765; 0 picks a free one)");
    cmd->add_flag("--open", args->open, "open the page in the default browser");
    cmd->add_option("--threads", args->threads, "render threads (0: every core, the default)");
    cmd->add_option("--timeout", args->timeout,
                    "stop serving after SECONDS (also bounds implicitizing the input)");
    cmd->callback([args, &context] { context.exit_code = run_view(*args); });
}

}  // namespace locus::cli
