// tools/linework/farm_plan.h — a shot cut into tasks for a render farm (`linework farm`).
//
// Input:  the shot (frames A:B), the chunk length, the mode (exact or warm-up), the
//         `linework render` arguments that shape the frames, and the farm folder.
// Output: a FarmPlan — phases of tasks, each a plain `linework render` command line with the
//         frames it writes and the tasks it needs — written as DIR/plan.json (what any
//         scheduler needs) and as a Slurm submission (one job array per phase).
//
// Frames are not independent: each frame's stroke parameterization is fitted from the
// previous frame's (the SLAM paper, §4). Exact mode therefore runs the temporal state alone
// through the shot first (phase "state": no shading, strokes or files) and saves it at every
// chunk start; each chunk of phase "frames" restores its state and draws frames identical to
// one render of the whole range. Warm-up mode has one phase: each chunk draws K frames before
// its own without writing them, and starts close to, not at, the one-machine state.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/camera_path.h"

namespace lw::cli {

struct FarmTask {
    std::string id;                    // "state", "frames_0003"
    FrameRange frames;                 // drawn and written (the state task: drawn, states written)
    std::vector<std::string> command;  // argv, the linework binary first
    std::vector<std::string> after;    // ids of the tasks it needs
};

struct FarmPhase {
    std::string name;  // "state" or "frames"
    std::vector<FarmTask> tasks;
};

struct FarmRequest {
    std::filesystem::path linework;    // the binary the tasks run (absolute)
    std::filesystem::path dir;         // the farm folder (absolute)
    std::filesystem::path working_dir; // where the tasks run: relative paths in `arguments` hold there
    std::vector<std::string> arguments;  // the frame-shaping render arguments, the scene first
    // The same less --svg and --exr, which --state-only refuses: the state task's. The other
    // frame options stay, so that its states carry the chunks' signature.
    std::vector<std::string> state_arguments;
    FrameRange frames;
    int chunk = 0;
    bool exact = true;
    int warmup = 0;  // warm-up mode: frames drawn before each chunk
};

struct FarmPlan {
    FarmRequest request;
    std::vector<FarmPhase> phases;
    std::filesystem::path output() const { return request.dir / "frames"; }
    std::filesystem::path states() const { return request.dir / "states"; }
    std::filesystem::path logs() const { return request.dir / "logs"; }
    // logs/PHASE_NNNN.log and .rc: task `index` of a phase, numbered as Slurm's %4a numbers
    // an array task's output, so that a task's log and exit status sort and read together.
    std::filesystem::path task_file(const std::string& phase, size_t index, const char* extension) const;
};

// Throws a usage error for a chunk under 1 or a warm-up under 0.
[[nodiscard]] FarmPlan plan_farm(const FarmRequest& request);

[[nodiscard]] nlohmann::json plan_json(const FarmPlan& plan);
// Reads DIR/plan.json back (farm status); errors name the file and the key.
[[nodiscard]] FarmPlan read_plan(const std::filesystem::path& dir);

// DIR/slurm/phase_N_NAME.sbatch (one job array per phase, --requeue, a log per task, a task
// killed by a signal run again) and DIR/slurm/submit.sh (the arrays chained with afterok).
// `throttle`: at most this many tasks of an array at once (0: no limit).
void write_slurm_scripts(const FarmPlan& plan, int throttle, int cpus_per_task);

// A command line for a shell, each argument quoted where it needs it.
[[nodiscard]] std::string shell_line(const std::vector<std::string>& argv);

}  // namespace lw::cli
