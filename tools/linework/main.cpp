// tools/linework/main.cpp — the `linework` command: one binary, one subcommand per job.
//
// Exit codes: 0 success; 1 bad input or a failed run (the message names the file and the
// problem); 2 bad command-line usage.
#include <algorithm>
#include <cstdio>
#include <string>
#include <exception>
#include <utility>
#include <vector>

#include <unistd.h>

#include "cli_errors.h"
#include "commands.h"
#include "core/error.h"
#include "core/memory.h"

namespace {

// Edit distance (insertions, deletions, substitutions, transpositions of neighbours).
size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// A first word that is no command: one line naming it, with the nearest command when one
// is within two edits or starts with it (CLI11 would only say a subcommand is required).
bool refuse_unknown_command(const CLI::App& app, const std::string& word) {
    if (word.empty() || word[0] == '-') return false;
    std::string best;
    size_t best_distance = 3;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
        const std::string& name = sub->get_name();
        if (name == word) return false;
        const size_t d = name.rfind(word, 0) == 0 ? 1 : edit_distance(word, name);
        if (d < best_distance) best_distance = d, best = name;
    }
    std::string hint;
    if (!best.empty()) hint.append("; did you mean '").append(best).append("'?");
    std::fprintf(stderr, "linework: error: unknown command '%s'%s (linework --help lists them)\n", word.c_str(), hint.c_str());
    return true;
}

}  // namespace

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

    if (argc > 1 && refuse_unknown_command(app, argv[1])) return 2;
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // As every other error: one line with the tool's prefix (CLI11's own print has none).
        std::fprintf(stderr, "linework: error: %s\nRun with --help for more information.\n",
                     lw::cli::parse_error_text(e, app, argc, argv).c_str());
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
