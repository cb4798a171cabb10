// tools/linework/main.cpp — the `linework` command: one binary, one subcommand per job.
//
// Exit codes: 0 success; 1 bad input or a failed run (the message names the file and the
// problem); 2 bad command-line usage.
#include <cstdio>
#include <exception>
#include <utility>
#include <vector>

#include <unistd.h>

#include "commands.h"
#include "core/error.h"
#include "core/memory.h"

int main(int argc, char** argv) {
    lw::keep_freed_memory();  // before any thread: lavapipe reallocates megabytes every frame
    // Line by line into a log (a farm task's): a task killed by SIGKILL keeps what it printed.
    if (!isatty(fileno(stdout))) std::setvbuf(stdout, nullptr, _IOLBF, 0);
    CLI::App app{"linework — real-time line stylization on Vulkan.\n"
                 "Renders glTF models and scene files headlessly (Mesa lavapipe or a GPU), or in a window (view)."};
    app.require_subcommand(1);
    app.set_version_flag("--version", "linework 0.1.0");

    std::vector<std::pair<CLI::App*, lw::cli::Runner>> commands;
    auto add = [&](lw::cli::Runner (*adder)(CLI::App&)) {
        const size_t before = app.get_subcommands({}).size();
        lw::cli::Runner runner = adder(app);
        commands.emplace_back(app.get_subcommands({})[before], std::move(runner));
    };
    add(&lw::cli::add_render_command);
    add(&lw::cli::add_farm_command);
    add(&lw::cli::add_diff_command);
    add(&lw::cli::add_devices_command);
    add(&lw::cli::add_slam_command);
    add(&lw::cli::add_slam_pattern_command);
    add(&lw::cli::add_coherence_report_command);
    add(&lw::cli::add_ribbon_command);
    add(&lw::cli::add_ribbon_exemplar_command);
    add(&lw::cli::add_pattern_command);
    add(&lw::cli::add_hatch_command);
    add(&lw::cli::add_view_command);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    }

    try {
        for (auto& [subcommand, runner] : commands)
            // Every command that takes a device names it with --device and --compute.
            if (subcommand->parsed())
                return lw::cli::flags_named({{"device", "--device"}, {"compute", "--compute"}}, runner);
    } catch (const lw::Error& e) {
        std::fprintf(stderr, "linework: error: %s\n", e.what());
        return e.exit_code();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "linework: internal error: %s\n", e.what());
        return 1;
    }
    return 0;
}
