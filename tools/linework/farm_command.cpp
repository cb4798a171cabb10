// `linework farm SCENE -o DIR --frames A:B --chunk N [--exact | --warmup K]` — a shot cut
// into tasks for a render farm (farm_plan.h); `linework farm status DIR`: which frames are
// finished, missing, or left by a failed task; `linework farm task DIR PHASE I`: one task.
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "commands.h"
#include "farm_plan.h"
#include "render_options.h"
#include "render_output.h"
#include "render_state.h"

namespace lw::cli {

namespace {

struct FarmOptions {
    RenderOptions render;  // the frame options handed on to every task
    std::string dir, frames, status_dir, task_dir, task_phase;
    int task_index = -1;
    int chunk = 0, warmup = -1, throttle = 0, cpus_per_task = 1;
    bool exact = false;
};

// The options `farm` has itself: not handed on.
const std::vector<std::string> kFarmOwn = {"--output", "--frames", "--chunk", "--exact",
                                           "--warmup", "--throttle", "--cpus-per-task"};

const std::vector<std::string> kStateTaskLeavesOut = [] {
    std::vector<std::string> names = kFarmOwn;
    names.insert(names.end(), {"--svg", "--exr"});
    return names;
}();

std::filesystem::path this_binary() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw Error("farm: cannot find the linework binary (/proc/self/exe: " + ec.message() + ")");
    return exe;
}

int run_farm(const FarmOptions& o, const CLI::App& cmd) {
    if (o.dir.empty()) throw usage_error("farm: --output (-o) DIR is required");
    if (o.frames.empty()) throw usage_error("farm: --frames A:B is required (the shot)");
    if (o.chunk < 1)
        throw usage_error(cmd.count("--chunk") > 0 ? "--chunk: must be 1 or more frames per task, got " + std::to_string(o.chunk)
                                                   : std::string("farm: --chunk N (frames per task, 1 or more) is required"));
    if (o.warmup < -1 || (o.warmup == -1 && cmd.count("--warmup") > 0))
        throw usage_error("--warmup: must be 0 or more");
    if (o.exact == (o.warmup >= 0)) throw usage_error("farm: choose --exact or --warmup K (one of them)");
    if (o.throttle < 0) throw usage_error("--throttle: must be 0 (no limit) or more");
    if (o.cpus_per_task < 1) throw usage_error("--cpus-per-task: must be 1 or more");
    FarmRequest request{.linework = this_binary(),
                        .dir = std::filesystem::absolute(o.dir).lexically_normal(),
                        .working_dir = std::filesystem::current_path(),
                        .arguments = given_arguments(cmd, kFarmOwn),
                        .state_arguments = given_arguments(cmd, kStateTaskLeavesOut),
                        .frames = parse_frames(o.frames),
                        .chunk = o.chunk,
                        .exact = o.exact,
                        .warmup = std::max(o.warmup, 0)};
    // The frame options are checked here, once, rather than by every task on the farm.
    SceneDesc desc = scene_from_options(o.render.scene);
    check_flags_shape_drawn_lines(o.render.scene, desc.lines);
    apply_frame_overrides(o.render, desc);
    (void)camera_override(o.render);
    const FarmPlan plan = plan_farm(request);
    const std::filesystem::path plan_file = plan.request.dir / "plan.json";
    const std::string text = plan_json(plan).dump(2) + "\n";
    // The tasks resume what they find, so another shot's frames in the folder would pass
    // for this one's: a folder holds one plan (the same plan again is fine).
    if (std::filesystem::exists(plan_file)) {
        std::ifstream in(plan_file, std::ios::binary);
        const std::string old((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (old != text)
            throw Error(plan_file.string() + ": the folder holds another shot's plan; choose another -o folder, or "
                                             "remove this one to start over");
    }
    create_folder(plan.request.dir, "farm");
    create_folder(plan.logs(), "log");
    // The folders the tasks write beside the frames, made (and so checked) now as `render`
    // makes them before its first frame, rather than failing in every task.
    create_folders(FrameFiles{.svg = o.render.svg, .dump_paths = o.render.dump_paths});
    write_text_atomically(plan_file, text);
    write_slurm_scripts(plan, o.throttle, o.cpus_per_task);
    if (o.exact && o.render.scene.device == "auto")
        std::printf("note: --device auto: nodes with different devices (a GPU, lavapipe) give frames that differ in "
                    "the last bits; pin --device cpu or gpu for identical frames\n");
    const int chunks = int(plan.phases.back().tasks.size());
    std::printf("shot: frames %d to %d in %d chunk(s) of %d, %s\n", request.frames.first, request.frames.last, chunks,
                request.chunk,
                !o.exact                  ? ("each after " + std::to_string(request.warmup) + " warm-up frames").c_str()
                : plan.phases.size() == 1 ? "exact (one chunk: no state phase)"
                                          : "exact (a state phase first)");
    for (const FarmPhase& phase : plan.phases)
        std::printf("phase %s: %zu task(s)\n", phase.name.c_str(), phase.tasks.size());
    std::printf("wrote %s\n", plan_file.string().c_str());
    std::printf("wrote %s/slurm/submit.sh (run it to submit; then: linework farm status %s)\n",
                plan.request.dir.string().c_str(), plan.request.dir.string().c_str());
    // sbatch installed without a cluster fails at submission with its own "fatal: …": say so
    // now, and what runs the tasks without Slurm. (A bounded wait: a controller that is down
    // can keep sinfo retrying.)
    if (std::system("timeout 5 sinfo --noheader > /dev/null 2>&1") != 0)
        std::printf("note: no Slurm controller answers here (sinfo): submit.sh needs a cluster; without one, run "
                    "each task with linework farm task %s PHASE I (README \"Render farm\")\n",
                    plan.request.dir.string().c_str());
    return 0;
}

// "3-5, 9" from a sorted list of frames.
std::string frame_list(const std::vector<int>& frames) {
    std::string text;
    for (size_t i = 0; i < frames.size();) {
        size_t j = i;
        while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
        if (!text.empty()) text += ", ";
        text += std::to_string(frames[i]) + (j > i ? "-" + std::to_string(frames[j]) : "");
        i = j + 1;
    }
    return text;
}

// The last exit status a task's Slurm script recorded (-1: it has not run under it).
int recorded_exit(const FarmPlan& plan, const FarmPhase& phase, size_t index) {
    std::ifstream in(plan.task_file(phase.name, index, ".rc"));
    int rc = -1;
    if (in >> rc) return rc;
    return -1;
}

// What the frames tasks write per frame, read back from the options the plan hands them
// (given_arguments: "--svg" and "--dump-paths" each followed by its value; relative to the
// working folder), so that a frame is finished only when its EXR, SVG and dump are there too.
FrameFiles plan_frame_files(const FarmPlan& plan) {
    FrameFiles files{.out_dir = plan.output(), .sequence = true};
    const std::vector<std::string>& a = plan.request.arguments;
    for (size_t i = 0; i < a.size(); ++i) {
        const auto value = [&] { return i + 1 < a.size() ? (plan.request.working_dir / a[i + 1]).string() : std::string(); };
        if (a[i] == "--exr") files.exr = true;
        if (a[i] == "--svg") files.svg = value();
        if (a[i] == "--dump-paths") files.dump_paths = value();
    }
    return files;
}

// One line per task; returns whether it is finished (every frame, or every state, there).
bool report_task(const FarmPlan& plan, const FarmPhase& phase, size_t index, std::vector<int>& missing_frames,
                 int& failed) {
    const FarmRequest& r = plan.request;
    const FarmTask& task = phase.tasks[index];
    std::vector<int> missing;
    int wanted = 0;
    if (phase.name == "state") {
        for (int start = r.frames.first + r.chunk; start <= task.frames.last + 1; start += r.chunk, ++wanted)
            if (!std::filesystem::exists(saved_state_path(plan.states(), start))) missing.push_back(start);
    } else {
        const FrameFiles files = plan_frame_files(plan);
        for (int f = task.frames.first; f <= task.frames.last; ++f, ++wanted)
            if (!frame_written(files, f)) missing.push_back(f);
        missing_frames.insert(missing_frames.end(), missing.begin(), missing.end());
    }
    const int rc = recorded_exit(plan, phase, index);
    // Stopped (Ctrl-C, scancel's SIGTERM: 130, 143) is not failed: run again, it resumes.
    const bool stopped = !missing.empty() && (rc == 130 || rc == 143);
    const bool task_failed = !missing.empty() && rc > 0 && !stopped;
    failed += task_failed;
    std::printf("  %-12s frames %d-%d: ", task.id.c_str(), task.frames.first, task.frames.last);
    if (missing.empty()) {
        std::printf("finished\n");
        return true;
    }
    std::printf("%d of %d %s written, missing %s", wanted - int(missing.size()), wanted,
                phase.name == "state" ? "states (at chunk starts)" : "frames", frame_list(missing).c_str());
    const std::string log = plan.task_file(phase.name, index, ".log").string();
    if (task_failed) std::printf("; failed (exit %d, see %s)", rc, log.c_str());
    if (stopped) std::printf("; stopped (exit %d): run it again to go on", rc);
    std::printf("\n");
    return false;
}

int run_status(const std::string& dir) {
    const FarmPlan plan = read_plan(dir);
    const FarmRequest& r = plan.request;
    std::printf("shot: frames %d to %d, chunks of %d, %s; frames in %s\n", r.frames.first, r.frames.last, r.chunk,
                r.exact ? "exact" : ("warm-up " + std::to_string(r.warmup)).c_str(), plan.output().string().c_str());
    std::vector<int> missing;
    int failed = 0;
    for (const FarmPhase& phase : plan.phases) {
        std::printf("phase %s:\n", phase.name.c_str());
        for (size_t t = 0; t < phase.tasks.size(); ++t) report_task(plan, phase, t, missing, failed);
    }
    const int total = r.frames.last - r.frames.first + 1;
    std::printf("frames: %d of %d finished", total - int(missing.size()), total);
    if (!missing.empty()) std::printf("; missing %s", frame_list(missing).c_str());
    if (failed) std::printf("; %d task(s) failed", failed);
    std::printf("\n");
    // A failed task is not "not yet": a loop waiting for the shot must be able to stop.
    return failed ? 1 : missing.empty() ? 0 : 3;
}

volatile sig_atomic_t g_task_pid = 0;

void forward_to_task(int signal) {
    if (g_task_pid > 0) kill(pid_t(g_task_pid), signal);
}

// While the task runs, SIGINT and SIGTERM to `farm task` go on to it, so that it finishes
// its frame and exits 130 (what README "Render farm" promises), and the task's status is
// recorded; the task has a process group of its own, so that a Ctrl-C at a terminal reaches
// it once, through here (twice would stop it at once, without the frame in hand).
class ForwardStopSignals {
public:
    explicit ForwardStopSignals(pid_t task) {
        g_task_pid = task;
        struct sigaction forward {};
        forward.sa_handler = forward_to_task;
        sigemptyset(&forward.sa_mask);
        sigaction(SIGINT, &forward, &int_);
        sigaction(SIGTERM, &forward, &term_);
    }
    ~ForwardStopSignals() {
        sigaction(SIGINT, &int_, nullptr);
        sigaction(SIGTERM, &term_, nullptr);
        g_task_pid = 0;
    }
    ForwardStopSignals(const ForwardStopSignals&) = delete;
    ForwardStopSignals& operator=(const ForwardStopSignals&) = delete;

private:
    struct sigaction int_ {}, term_ {};
};

// Runs `command` with its output passed through to ours and appended to `log`; returns its
// exit status (128 + the signal's number when a signal ended it, as a shell reports it).
int run_logged(const std::vector<std::string>& command, const std::filesystem::path& log) {
    int pipe_ends[2];
    if (pipe(pipe_ends) != 0) throw Error(std::string("farm task: cannot make a pipe (") + std::strerror(errno) + ")");
    std::fflush(stdout);
    // A stop signal that comes before the forwarding is in place waits for it (blocked, then
    // delivered and passed on), rather than ending this process and leaving the task running.
    sigset_t stops, before;
    sigemptyset(&stops);
    sigaddset(&stops, SIGINT);
    sigaddset(&stops, SIGTERM);
    sigprocmask(SIG_BLOCK, &stops, &before);
    const pid_t parent = getpid();
    const pid_t child = fork();
    if (child < 0) {
        sigprocmask(SIG_SETMASK, &before, nullptr);
        throw Error(std::string("farm task: cannot start the task (") + std::strerror(errno) + ")");
    }
    if (child == 0) {
        setpgid(0, 0);
        // Killed outright (SIGKILL, a group kill that now misses the task's own group), this
        // process can pass nothing on: the task is stopped as by SIGTERM instead.
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        if (getppid() != parent) _exit(143);  // it died before the line above
        sigprocmask(SIG_SETMASK, &before, nullptr);
        dup2(pipe_ends[1], STDOUT_FILENO);
        dup2(pipe_ends[1], STDERR_FILENO);
        close(pipe_ends[0]);
        close(pipe_ends[1]);
        std::vector<char*> argv;
        for (const std::string& a : command) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        std::fprintf(stderr, "linework: error: %s: cannot run (%s)\n", command[0].c_str(), std::strerror(errno));
        _exit(127);
    }
    close(pipe_ends[1]);
    const ForwardStopSignals forward(child);
    sigprocmask(SIG_SETMASK, &before, nullptr);
    std::ofstream out(log, std::ios::app | std::ios::binary);
    char buffer[4096];
    for (ssize_t n; (n = read(pipe_ends[0], buffer, sizeof buffer)) != 0;) {
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) break;
        (void)!write(STDOUT_FILENO, buffer, size_t(n));
        out.write(buffer, n);
        out.flush();
    }
    close(pipe_ends[0]);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 1;
}

// `farm task DIR PHASE I`: runs task I of the phase in the plan's working folder, so that a
// scheduler that hands out numbered tasks (OpenCue's frames of a layer, Deadline's frames of a
// job) needs no script of ours. As the Slurm script does, it appends the task's output to
// logs/PHASE_NNNN.log and records its exit status in logs/PHASE_NNNN.rc for `farm status`;
// the exit code is the task's.
int run_task(const FarmOptions& o) {
    const FarmPlan plan = read_plan(o.task_dir);
    const auto phase = std::find_if(plan.phases.begin(), plan.phases.end(),
                                    [&](const FarmPhase& p) { return p.name == o.task_phase; });
    if (phase == plan.phases.end())
        throw usage_error("farm task: the plan in " + o.task_dir + " has no phase \"" + o.task_phase + "\"");
    if (o.task_index < 0 || size_t(o.task_index) >= phase->tasks.size())
        throw usage_error("farm task: phase " + o.task_phase + " has tasks 0 to " +
                          std::to_string(phase->tasks.size() - 1) + ", not " + std::to_string(o.task_index));
    const FarmTask& task = phase->tasks[size_t(o.task_index)];
    std::error_code ec;
    std::filesystem::current_path(plan.request.working_dir, ec);
    if (ec) throw Error(plan.request.working_dir.string() + ": cannot run the task there (" + ec.message() + ")");
    create_folder(plan.logs(), "log");
    const std::filesystem::path log = plan.task_file(phase->name, size_t(o.task_index), ".log");
    const std::filesystem::path rc_file = plan.task_file(phase->name, size_t(o.task_index), ".rc");
    std::printf("linework farm: task %s: %s\n", task.id.c_str(), shell_line(task.command).c_str());
    std::ofstream(log, std::ios::app) << "linework farm: task " << task.id << ": " << shell_line(task.command) << "\n";
    std::filesystem::remove(rc_file, ec);  // running: not failed, whatever an earlier run said
    const int rc = run_logged(task.command, log);
    std::ofstream(rc_file) << rc << "\n";
    return rc;
}

}  // namespace

Runner add_farm_command(CLI::App& app) {
    auto o = std::make_shared<FarmOptions>();
    CLI::App* cmd = app.add_subcommand(
        "farm",
        "Cut a shot into tasks for a render farm: DIR/plan.json (the tasks, plain `linework render` command lines, "
        "and their dependencies) and DIR/slurm/submit.sh (one Slurm job array per phase).\n"
        "--exact: a first task runs only the temporal state through the shot and saves it at each chunk start; "
        "the chunks then restore it and give frames identical to one render of the whole range.\n"
        "--warmup K: one phase; each chunk draws K frames before its own: a settled start, but the strokes' phase "
        "restarts at each chunk (README \"Render farm\"): for untextured lines.\n"
        "Frames go to DIR/frames, logs to DIR/logs. Takes render's options for the frames.");
    cmd->positionals_at_end(false);
    add_frame_options(cmd, o->render);
    cmd->get_option("input")->required(false);  // `farm status DIR` has none; checked below
    cmd->add_option("-o,--output", o->dir, "Farm folder: plan.json, slurm/, frames/, states/, logs/");
    cmd->add_option("--frames", o->frames, "The shot, A:B inclusive");
    cmd->add_option("--chunk", o->chunk, "Frames per task");
    cmd->add_flag("--exact", o->exact, "Frames identical to one render of the range (a state phase first)");
    cmd->add_option("--warmup", o->warmup, "Each chunk draws K frames before its own, unwritten (no state phase)");
    cmd->add_option("--throttle", o->throttle, "At most N tasks of a phase at once (Slurm --array %N; 0: no limit)");
    cmd->add_option("--cpus-per-task", o->cpus_per_task, "CPUs Slurm gives each task (default 1)");

    CLI::App* status = cmd->add_subcommand("status", "List a farm folder's finished, missing and failed frames "
                                                     "(exit 0 when every frame is there, 3 when some are still missing, 1 when a task "
                                                     "failed)");
    status->add_option("dir", o->status_dir, "Farm folder (made by linework farm)")->required();
    CLI::App* task = cmd->add_subcommand("task", "Run task I of a phase of the plan (for schedulers that hand out "
                                                 "numbered tasks: OpenCue, Deadline; README \"Render farm\")");
    task->add_option("dir", o->task_dir, "Farm folder (made by linework farm)")->required();
    task->add_option("phase", o->task_phase, "Phase: state or frames")->required();
    task->add_option("index", o->task_index, "Task number within the phase, from 0")->required();
    cmd->require_subcommand(0, 1);
    return [o, cmd, status, task] {
        if (status->parsed()) return run_status(o->status_dir);
        if (task->parsed()) return run_task(*o);
        if (o->render.scene.input.empty()) throw usage_error("farm: a scene file or model is required");
        return run_farm(*o, *cmd);
    };
}

}  // namespace lw::cli
