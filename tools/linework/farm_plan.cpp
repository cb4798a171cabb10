#include "farm_plan.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "core/error.h"
#include "core/text.h"
#include "render_state.h"

namespace lw::cli {

namespace {

std::string padded(int n) {
    char text[16];
    std::snprintf(text, sizeof text, "%04d", n);
    return text;
}

std::string range_text(FrameRange r) { return std::to_string(r.first) + ":" + std::to_string(r.last); }

// `linework render` with the shot's own arguments, then the task's.
std::vector<std::string> render_command(const FarmRequest& r, std::initializer_list<std::string> task_arguments) {
    std::vector<std::string> argv{r.linework.string(), "render"};
    argv.insert(argv.end(), r.arguments.begin(), r.arguments.end());
    argv.push_back("--frames");
    argv.push_back(range_text(r.frames));
    argv.insert(argv.end(), task_arguments);
    return argv;
}

}  // namespace

std::filesystem::path FarmPlan::task_file(const std::string& phase, size_t index, const char* extension) const {
    return logs() / (phase + "_" + padded(int(index)) + extension);
}

FarmPlan plan_farm(const FarmRequest& request) {
    if (request.chunk < 1) throw usage_error("--chunk: must be 1 or more frames");
    if (request.warmup < 0) throw usage_error("--warmup: must be 0 or more");
    FarmPlan plan{.request = request};
    const FarmRequest& r = request;
    const std::string frames = plan.output().string();
    std::vector<FrameRange> chunks;
    for (int c = r.frames.first; c <= r.frames.last; c += r.chunk)
        chunks.push_back({c, std::min(c + r.chunk - 1, r.frames.last)});

    const bool state_phase = r.exact && chunks.size() > 1;
    if (state_phase) {
        // Through the frame before the last chunk: its state is the last one needed.
        const FrameRange drawn{r.frames.first, chunks.back().first - 1};
        FarmRequest state_request = r;
        state_request.arguments = r.state_arguments;
        plan.phases.push_back(
            {"state",
             {{.id = "state",
               .frames = drawn,
               .command = render_command(state_request, {"--part", range_text(drawn), "--state-only", "--save-states",
                                                         plan.states().string(), "--chunk", std::to_string(r.chunk),
                                                         "--resume"}),
               .after = {}}}});
    }
    FarmPhase phase{.name = "frames"};
    for (size_t k = 0; k < chunks.size(); ++k) {
        const FrameRange c = chunks[k];
        FarmTask task{.id = "frames_" + padded(int(k)), .frames = c};
        task.command = render_command(r, {"--part", range_text(c), "-o", frames, "--resume"});
        if (r.exact && k > 0) {
            task.command.push_back("--start-state");
            task.command.push_back(saved_state_path(plan.states(), c.first).string());
            task.after = {"state"};
        } else if (!r.exact && r.warmup > 0 && k > 0) {
            // Never before the shot's first frame: a chunk that close starts where one render does.
            task.command.push_back("--warmup");
            task.command.push_back(std::to_string(std::min(r.warmup, c.first - r.frames.first)));
        }
        phase.tasks.push_back(std::move(task));
    }
    plan.phases.push_back(std::move(phase));
    return plan;
}

nlohmann::json plan_json(const FarmPlan& plan) {
    const FarmRequest& r = plan.request;
    nlohmann::json phases = nlohmann::json::array();
    for (const FarmPhase& phase : plan.phases) {
        nlohmann::json tasks = nlohmann::json::array();
        for (const FarmTask& t : phase.tasks)
            tasks.push_back({{"id", t.id},
                             {"frames", {t.frames.first, t.frames.last}},
                             {"after", t.after},
                             {"command", t.command},
                             {"shell", shell_line(t.command)}});
        phases.push_back({{"name", phase.name}, {"tasks", tasks}});
    }
    return {{"linework_farm", 1},
            {"mode", r.exact ? "exact" : "warmup"},
            {"warmup", r.warmup},
            {"frames", {r.frames.first, r.frames.last}},
            {"chunk", r.chunk},
            {"linework", r.linework.string()},
            {"working_directory", r.working_dir.string()},
            {"arguments", r.arguments},
            {"output", plan.output().string()},
            {"states", plan.states().string()},
            {"logs", plan.logs().string()},
            {"phases", phases}};
}

FarmPlan read_plan(const std::filesystem::path& dir) {
    const std::filesystem::path file = dir / "plan.json";
    std::ifstream in(file);
    if (!in) throw Error(file.string() + ": no farm plan here (made by `linework farm SCENE -o " + dir.string() + " …`)");
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        if (j.at("linework_farm").get<int>() != 1) throw Error(file.string() + ": a farm plan of another version");
        FarmPlan plan;
        FarmRequest& r = plan.request;
        r.dir = dir;
        r.exact = j.at("mode").get<std::string>() == "exact";
        r.warmup = j.at("warmup").get<int>();
        r.frames = {j.at("frames").at(0).get<int>(), j.at("frames").at(1).get<int>()};
        r.chunk = j.at("chunk").get<int>();
        r.linework = j.at("linework").get<std::string>();
        r.working_dir = j.at("working_directory").get<std::string>();
        r.arguments = j.at("arguments").get<std::vector<std::string>>();
        // The tasks' command lines name the folder the plan was made for: a plan copied or moved
        // elsewhere would run tasks that write there while `farm status` looked here.
        const std::filesystem::path made_for = std::filesystem::path(j.at("output").get<std::string>()).parent_path();
        std::error_code ec;
        if (!std::filesystem::equivalent(made_for, dir, ec))
            throw Error(file.string() + ": a plan made for " + made_for.string() +
                        " (its tasks write there); plan the shot again in this folder with `linework farm … -o " +
                        dir.string() + "`");
        for (const nlohmann::json& p : j.at("phases")) {
            FarmPhase phase{.name = p.at("name").get<std::string>()};
            for (const nlohmann::json& t : p.at("tasks"))
                phase.tasks.push_back({.id = t.at("id").get<std::string>(),
                                       .frames = {t.at("frames").at(0).get<int>(), t.at("frames").at(1).get<int>()},
                                       .command = t.at("command").get<std::vector<std::string>>(),
                                       .after = t.at("after").get<std::vector<std::string>>()});
            plan.phases.push_back(std::move(phase));
        }
        if (r.chunk < 1 || r.frames.last < r.frames.first || plan.phases.empty())
            throw Error(file.string() + ": not a farm plan (chunk, frames or phases out of range)");
        for (const FarmPhase& phase : plan.phases) {
            if (phase.tasks.empty()) throw Error(file.string() + ": phase " + phase.name + " has no tasks");
            for (const FarmTask& t : phase.tasks)
                if (t.command.empty()) throw Error(file.string() + ": task " + t.id + " has no command");
        }
        return plan;
    } catch (const nlohmann::json::exception& e) {
        throw Error(file.string() + ": not a farm plan (" + json_message(e.what()) + ")");
    }
}

std::string shell_line(const std::vector<std::string>& argv) {
    std::string line;
    for (const std::string& a : argv) {
        if (!line.empty()) line += ' ';
        const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                             "0123456789-_./:=,+%@") == std::string::npos;
        if (plain) {
            line += a;
            continue;
        }
        line += '\'';
        for (const char ch : a) line += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
        line += '\'';
    }
    return line;
}

}  // namespace lw::cli
