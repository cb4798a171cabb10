// The Slurm side of a farm plan (farm_plan.h): one batch script per phase, run as a job
// array (task i of the array is task i of the phase), and a submit script chaining the
// arrays with afterok. Tasks are resumable (`render --resume`), so a requeued or re-run
// task goes on from the frames and state it wrote.
#include <cstdio>

#include "core/error.h"
#include "farm_plan.h"
#include "render_state.h"

namespace lw::cli {

namespace {

void write_script(const std::filesystem::path& path, const std::string& text) {
    write_text_atomically(path, text);
    using std::filesystem::perms;
    std::error_code ec;
    std::filesystem::permissions(path, perms::owner_exec | perms::group_exec | perms::others_exec,
                                 std::filesystem::perm_options::add, ec);
    if (ec) throw Error(path.string() + ": cannot make it executable (" + ec.message() + ")");
}

std::string phase_script(const FarmPlan& plan, size_t index, int throttle, int cpus_per_task) {
    const FarmPhase& phase = plan.phases[index];
    const std::string logs = plan.logs().string();
    const std::string shot = plan.request.dir.filename().string();
    std::string s = "#!/usr/bin/env bash\n";
    s += "# Phase " + std::to_string(index + 1) + " of the shot's plan.json: \"" + phase.name + "\", " +
         std::to_string(phase.tasks.size()) + " task(s); array task i runs task i.\n";
    s += "#SBATCH --job-name=" + shell_line({"lw-" + shot + "-" + phase.name}) + "\n";
    s += "#SBATCH --array=0-" + std::to_string(phase.tasks.size() - 1) +
         (throttle > 0 ? "%" + std::to_string(throttle) : std::string()) + "\n";
    s += "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=" + std::to_string(cpus_per_task) + "\n";
    s += "#SBATCH --requeue\n";
    s += "#SBATCH --chdir=" + shell_line({plan.request.working_dir.string()}) + "\n";
    // Appended, so that a requeued task's log keeps the run it replaces.
    s += "#SBATCH --open-mode=append\n";
    s += "#SBATCH --output=" + shell_line({logs + "/" + phase.name + "_%4a.log"}) + "\n";
    s += "set -uo pipefail\n";
    s += "case \"${SLURM_ARRAY_TASK_ID:?run me through sbatch (submit.sh)}\" in\n";
    for (size_t t = 0; t < phase.tasks.size(); ++t)
        s += "  " + std::to_string(t) + ") id=" + phase.tasks[t].id + "; cmd=(" + shell_line(phase.tasks[t].command) +
             ") ;;\n";
    s += "  *) echo \"no task $SLURM_ARRAY_TASK_ID in this phase\" >&2; exit 2 ;;\n";
    s += "esac\n";
    s += "echo \"linework farm: task $id on $(hostname) at $(date -Is) (job ${SLURM_JOB_ID:-?})\"\n";
    // A task killed by a signal (SIGKILL, the OOM killer) runs again and resumes; a task
    // that failed on its input (exit 1, 2) or was stopped (130: SIGINT or scancel's
    // SIGTERM) does not.
    // The exit status is recorded once the task is over: while it runs (or runs again), an
    // earlier attempt's status would read as a failure to `farm status`.
    // The exit status beside the task's log: logs/PHASE_NNNN.rc (FarmPlan::task_file).
    s += "printf -v rc_file '%s/%s_%04d.rc' " + shell_line({logs, phase.name}) + " \"$SLURM_ARRAY_TASK_ID\"\n";
    s += "rm -f \"$rc_file\"\n";
    s += "for attempt in 1 2 3; do\n";
    s += "  \"${cmd[@]}\"; rc=$?\n";
    s += "  if [ \"$rc\" -le 128 ] || [ \"$rc\" -eq 130 ] || [ \"$rc\" -eq 143 ]; then break; fi\n";
    s += "  if [ \"$attempt\" -eq 3 ]; then\n";
    s += "    echo \"linework farm: task $id ended by signal $((rc - 128)) in each of 3 attempts; giving up\"\n";
    s += "  else\n";
    s += "    echo \"linework farm: task $id ended by signal $((rc - 128)); running it again (attempt $((attempt + 1)))\"\n";
    s += "  fi\n";
    s += "done\n";
    s += "echo \"$rc\" > \"$rc_file\"\n";
    s += "exit \"$rc\"\n";
    return s;
}

}  // namespace

void write_slurm_scripts(const FarmPlan& plan, int throttle, int cpus_per_task) {
    const std::filesystem::path dir = plan.request.dir / "slurm";
    create_folder(dir, "Slurm script");
    std::string submit =
        "#!/usr/bin/env bash\n"
        "# Submits the shot of plan.json to Slurm: one job array per phase, each phase after the one\n"
        "# before has succeeded (afterok). sbatch options such as the partition come from the\n"
        "# environment (SBATCH_PARTITION, SBATCH_ACCOUNT, …) or from extra arguments: ./submit.sh -p gpu\n"
        "set -euo pipefail\n"
        "cd \"$(dirname \"$0\")\"\n"
        "mkdir -p " + shell_line({plan.logs().string()}) + "\n"
        "previous=\n";
    for (size_t i = 0; i < plan.phases.size(); ++i) {
        const std::string name = "phase_" + std::to_string(i + 1) + "_" + plan.phases[i].name + ".sbatch";
        write_script(dir / name, phase_script(plan, i, throttle, cpus_per_task));
        submit += "job=$(sbatch --parsable ${previous:+--dependency=afterok:$previous} \"$@\" " + name + ")\n";
        submit += "job=${job%%;*}\n";  // --parsable prints "id;cluster" on a multi-cluster setup
        submit += "echo \"" + plan.phases[i].name + ": job $job (" + std::to_string(plan.phases[i].tasks.size()) +
                  " task(s))\"\n";
        submit += "previous=$job\n";
    }
    submit += "echo " + shell_line({"follow it with: squeue; linework farm status " + plan.request.dir.string()}) + "\n";
    write_script(dir / "submit.sh", submit);
}

}  // namespace lw::cli
