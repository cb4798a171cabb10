// `linework farm`: the plan (every frame in exactly one task, dependencies acyclic), the
// temporal state run alone (its states equal those of a full render), the plan's tasks run
// here in order giving the frames of one render, and the errors. The same shot through a
// real Slurm is tests/farm/farm_test.sh.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

nlohmann::json read_plan(const fs::path& dir) {
    std::ifstream in(dir / "plan.json");
    return nlohmann::json::parse(in);
}

const std::string kShot = test::quote(test::data_dir() / "models/spot/spot.glb") +
                          " --device cpu --size 96x72 --orbit 60 --slam " +
                          test::quote(test::source_dir() / "scenes/slams/dots.exr");

// Every frame of the range in exactly one task of the last phase; each task needs only
// tasks of earlier phases (so the dependencies are acyclic); the commands run this binary.
void check_plan(const nlohmann::json& plan, int first, int last) {
    std::map<std::string, size_t> phase_of;
    std::map<int, int> writers;
    const auto& phases = plan.at("phases");
    for (size_t p = 0; p < phases.size(); ++p)
        for (const auto& task : phases[p].at("tasks")) {
            const std::string id = task.at("id");
            EXPECT_FALSE(phase_of.count(id)) << "task id " << id << " twice";
            phase_of[id] = p;
            for (const std::string after : task.at("after")) {
                ASSERT_TRUE(phase_of.count(after)) << id << " needs " << after << ", not an earlier task";
                EXPECT_LT(phase_of[after], p) << id << " needs " << after << " of its own phase";
            }
            EXPECT_EQ(task.at("command").at(0).get<std::string>(), fs::canonical(LW_LINEWORK_EXE).string());
            if (p + 1 == phases.size())
                for (int f = task.at("frames").at(0); f <= task.at("frames").at(1).get<int>(); ++f) ++writers[f];
        }
    for (int f = first; f <= last; ++f) EXPECT_EQ(writers[f], 1) << "frame " << f << " is written by " << writers[f];
    EXPECT_EQ(writers.size(), size_t(last - first + 1));
}

TEST(Farm, PlanHasEveryFrameInExactlyOneTaskAndAcyclicDependencies) {
    const fs::path dir = test::temp_dir();
    for (const std::string mode : {"--exact", "--warmup 3"}) {
        const fs::path farm = dir / (mode == "--exact" ? "exact" : "warmup");
        const auto made = test::run_linework("farm " + kShot + " --frames 3:25 --chunk 5 " + mode + " -o " +
                                             test::quote(farm));
        ASSERT_EQ(made.exit_code, 0) << made.output;
        const nlohmann::json plan = read_plan(farm);
        check_plan(plan, 3, 25);
        const auto& chunks = plan.at("phases").back().at("tasks");
        ASSERT_EQ(chunks.size(), 5u);  // 3-7, 8-12, 13-17, 18-22, 23-25
        EXPECT_EQ(chunks.back().at("frames"), nlohmann::json({23, 25}));
        EXPECT_TRUE(fs::exists(farm / "slurm/submit.sh"));
        if (mode == "--exact") {
            ASSERT_EQ(plan.at("phases").size(), 2u);
            // The state task runs up to the last chunk's start and writes its state there.
            EXPECT_EQ(plan.at("phases")[0].at("tasks")[0].at("frames"), nlohmann::json({3, 22}));
            const std::string last = chunks.back().at("shell");
            EXPECT_NE(last.find("--start-state " + (farm / "states/state_0023.lwstate").string()), std::string::npos)
                << last;
        } else {
            ASSERT_EQ(plan.at("phases").size(), 1u);
            // Never warmed up before the shot's first frame.
            EXPECT_EQ(chunks[0].at("shell").get<std::string>().find("--warmup"), std::string::npos);
            EXPECT_NE(chunks[1].at("shell").get<std::string>().find("--warmup 3"), std::string::npos);
        }
    }
}

TEST(Farm, StateOnlyRunSavesTheStatesOfAFullRender) {
    const fs::path dir = test::temp_dir();
    const std::string range = " --frames 0:14 --chunk 5 --save-states ";
    const auto full = test::run_linework("render " + kShot + range + test::quote(dir / "full") + " -o " +
                                         test::quote(dir / "frames"));
    ASSERT_EQ(full.exit_code, 0) << full.output;
    const std::string alone = "render " + kShot + range + test::quote(dir / "alone") + " --state-only --resume";
    const auto first = test::run_linework(alone);
    ASSERT_EQ(first.exit_code, 0) << first.output;
    EXPECT_NE(first.output.find("wrote 2 states"), std::string::npos) << first.output;
    for (const char* name : {"state_0005.lwstate", "state_0010.lwstate"}) {
        const std::string a = read_bytes(dir / "full" / name), b = read_bytes(dir / "alone" / name);
        EXPECT_GT(a.size(), 1000u);
        EXPECT_TRUE(a == b) << name << ": the state run alone differs from the full render's";
    }
    // Resumed, it goes on from the last state there, and writes the same bytes again.
    fs::remove(dir / "alone/state_0010.lwstate");
    const auto resumed = test::run_linework(alone);
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("resuming at frame 5 from"), std::string::npos) << resumed.output;
    EXPECT_TRUE(read_bytes(dir / "full/state_0010.lwstate") == read_bytes(dir / "alone/state_0010.lwstate"));
    const auto done = test::run_linework(alone);
    EXPECT_NE(done.output.find("all states of frames 0 to 9 are already in"), std::string::npos) << done.output;
}

TEST(Farm, ExactPlanRunHereEqualsOneRender) {
    const fs::path dir = test::temp_dir();
    const auto one = test::run_linework("render " + kShot + " --frames 0:11 -o " + test::quote(dir / "one") +
                                        " --dump-paths " + test::quote(dir / "one_dumps"));
    ASSERT_EQ(one.exit_code, 0) << one.output;
    // --exr=false is given but off: it must not reach the tasks as --exr.
    const auto made = test::run_linework("farm " + kShot + " --frames 0:11 --chunk 4 --exact --exr=false -o " +
                                         test::quote(dir / "farm") + " --dump-paths " + test::quote(dir / "dumps"));
    ASSERT_EQ(made.exit_code, 0) << made.output;
    const nlohmann::json plan = read_plan(dir / "farm");
    for (const std::string a : plan.at("arguments")) EXPECT_NE(a, "--exr");
    // Last chunk first: a task needing the state phase must fail cleanly without it, and
    // `farm task` records the failure for `farm status` as the Slurm script does.
    const std::string last = std::to_string(plan.at("phases").back().at("tasks").size() - 1);
    const auto early = test::run_linework("farm task " + test::quote(dir / "farm") + " frames " + last);
    EXPECT_EQ(early.exit_code, 1) << early.output;
    EXPECT_NE(early.output.find("state_0008.lwstate: no render state"), std::string::npos) << early.output;
    const auto failed = test::run_linework("farm status " + test::quote(dir / "farm"));
    EXPECT_EQ(failed.exit_code, 1) << "a failed task, not 3 (not yet)";
    EXPECT_NE(failed.output.find("failed (exit 1, see"), std::string::npos) << failed.output;
    // The task's log and exit status side by side, numbered as the states are.
    const std::string stem = "frames_" + std::string(4 - std::min<size_t>(4, last.size()), '0') + last;
    std::ifstream log(dir / "farm/logs" / (stem + ".log"));
    const std::string logged((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    EXPECT_NE(logged.find("no render state"), std::string::npos) << logged;
    std::ifstream rc(dir / "farm/logs" / (stem + ".rc"));
    int recorded = -1;
    EXPECT_TRUE(rc >> recorded) << stem << ".rc";
    EXPECT_EQ(recorded, 1);
    // Each task as a scheduler without our scripts runs it: `farm task DIR PHASE I`.
    for (const auto& phase : plan.at("phases"))
        for (size_t i = 0; i < phase.at("tasks").size(); ++i) {
            const auto r = test::run_linework("farm task " + test::quote(dir / "farm") + " " +
                                              phase.at("name").get<std::string>() + " " + std::to_string(i));
            ASSERT_EQ(r.exit_code, 0) << phase.at("tasks")[i].at("id") << ": " << r.output;
        }
    for (int f = 0; f <= 11; ++f)
        EXPECT_TRUE(read_bytes(dir / "one" / test::frame_png(f)) == read_bytes(dir / "farm/frames" / test::frame_png(f)))
            << "frame " << f << " differs from one render";
    // The parameterization too: no phase error against one render's dumps, and a nonzero
    // one against another shot's (the measure can fail).
    const auto against = test::run_linework("coherence-report " + test::quote(dir / "dumps") + " --against " +
                                            test::quote(dir / "one_dumps") + " --max-p90 0");
    EXPECT_EQ(against.exit_code, 0) << against.output;
    EXPECT_NE(against.output.find("0 frame(s) with p90 over 0 periods"), std::string::npos) << against.output;
    ASSERT_EQ(test::run_linework("render " + kShot + " --frames 0:11 --param arclength -o " +
                                 test::quote(dir / "arclength") + " --dump-paths " + test::quote(dir / "arclength_dumps"))
                  .exit_code,
              0);
    const auto other = test::run_linework("coherence-report " + test::quote(dir / "arclength_dumps") + " --against " +
                                          test::quote(dir / "one_dumps") + " --max-p90 0.01");
    EXPECT_EQ(other.exit_code, 1) << other.output;
    EXPECT_NE(other.output.find("OVER THE BOUND"), std::string::npos) << other.output;

    // A task run again finds its frames there (idempotent), and status says the shot is done.
    const auto again = test::run_command("LINEWORK_VALIDATION=1 " +
                                         plan.at("phases").back().at("tasks")[1].at("shell").get<std::string>() + " 2>&1");
    EXPECT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find("all frames 4 to 7 are already in"), std::string::npos) << again.output;
    const auto status = test::run_linework("farm status " + test::quote(dir / "farm"));
    EXPECT_EQ(status.exit_code, 0) << status.output;
    EXPECT_NE(status.output.find("frames: 12 of 12 finished"), std::string::npos) << status.output;
    // The same plan again is fine; another shot in the same folder is refused (its tasks
    // would take these frames for theirs).
    EXPECT_EQ(test::run_linework("farm " + kShot + " --frames 0:11 --chunk 4 --exact --exr=false -o " +
                                 test::quote(dir / "farm") + " --dump-paths " + test::quote(dir / "dumps"))
                  .exit_code,
              0);
    const auto replanned = test::run_linework("farm " + kShot + " --frames 0:11 --chunk 4 --exact --hidden faint -o " +
                                              test::quote(dir / "farm"));
    EXPECT_EQ(replanned.exit_code, 1) << replanned.output;
    EXPECT_NE(replanned.output.find("plan.json: the folder holds another shot's plan"), std::string::npos)
        << replanned.output;
    fs::remove(dir / "farm/frames" / test::frame_png(5));
    const auto missing = test::run_linework("farm status " + test::quote(dir / "farm"));
    EXPECT_EQ(missing.exit_code, 3) << missing.output;
    EXPECT_NE(missing.output.find("3 of 4 frames written, missing 5"), std::string::npos) << missing.output;
    // A frame is finished when every file the tasks write for it is there, its dump too.
    fs::remove(dir / "dumps/frame_0006.json");
    const auto no_dump = test::run_linework("farm status " + test::quote(dir / "farm"));
    EXPECT_EQ(no_dump.exit_code, 3) << no_dump.output;
    EXPECT_NE(no_dump.output.find("2 of 4 frames written"), std::string::npos) << no_dump.output;
    // A plan copied into another folder is refused: its tasks would write into the first.
    fs::create_directories(dir / "copy");
    fs::copy_file(dir / "farm/plan.json", dir / "copy/plan.json");
    for (const std::string command : {"farm status ", "farm task "}) {
        const auto copied = test::run_linework(command + test::quote(dir / "copy") +
                                               (command == "farm task " ? " frames 0" : ""));
        EXPECT_EQ(copied.exit_code, 1) << copied.output;
        EXPECT_NE(copied.output.find("plan.json: a plan made for " + (dir / "farm").string() + " (its tasks write there)"),
                  std::string::npos)
            << copied.output;
    }
}

// SIGTERM to `farm task` (a scheduler's stop) goes on to its render, which finishes its frame
// and exits 130; the task records 130 and exits with it. It used to die at once and leave the
// render drawing on, orphaned, with no status recorded.
TEST(Farm, ATaskStoppedBySigtermStopsItsRender) {
    const fs::path dir = test::temp_dir();
    ASSERT_EQ(test::run_linework("farm " + kShot + " --frames 0:999 --chunk 1000 --warmup 0 -o " +
                                 test::quote(dir / "farm"))
                  .exit_code,
              0);
    const std::string exe = LW_LINEWORK_EXE;
    const fs::path frames = dir / "farm/frames";
    const auto stopped = test::run_command(
        "LINEWORK_VALIDATION=1 '" + exe + "' farm task " + test::quote(dir / "farm") +
        " frames 0 > /dev/null 2>&1 & pid=$!; i=0; while [ ! -f " + test::quote(frames / test::frame_png(2)) +
        " ] && [ $i -lt 6000 ]; do sleep 0.01; i=$((i + 1)); if ! kill -0 $pid 2>/dev/null; then break; fi; "
        "done; kill -TERM $pid; wait $pid; echo $?");
    // However the test ends, no render of this shot outlives it.
    struct Reaper {
        std::string pattern;
        ~Reaper() { (void)test::run_command("pkill -KILL -f " + pattern + " 2>/dev/null"); }
    } reaper{test::quote((dir / "farm").string())};
    EXPECT_EQ(stopped.output, "130\n");
    std::ifstream rc(dir / "farm/logs/frames_0000.rc");
    int recorded = -1;
    EXPECT_TRUE(rc >> recorded);
    EXPECT_EQ(recorded, 130);
    // Nothing draws on once the task has exited.
    size_t written = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(frames)) ++written;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    size_t later = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(frames)) ++later;
    EXPECT_EQ(later, written);
    EXPECT_LT(written, 1000u);
}

TEST(Farm, BadRequestsAreOneClearError) {
    const fs::path dir = test::temp_dir();
    const auto neither = test::run_linework("farm " + kShot + " --frames 0:9 --chunk 5 -o " + test::quote(dir / "f"));
    EXPECT_EQ(neither.exit_code, 2);
    EXPECT_NE(neither.output.find("choose --exact or --warmup K"), std::string::npos) << neither.output;
    const auto bad_size = test::run_linework("farm " + kShot + " --frames 0:9 --chunk 5 --exact --size 1x1x1 -o " +
                                             test::quote(dir / "f"));
    EXPECT_NE(bad_size.exit_code, 0) << "a bad frame option must fail at planning, not on the farm";
    EXPECT_FALSE(fs::exists(dir / "f/plan.json"));
    const auto no_chunk = test::run_linework("farm " + kShot + " --frames 0:9 --exact -o " + test::quote(dir / "f"));
    EXPECT_EQ(no_chunk.exit_code, 2);
    EXPECT_NE(no_chunk.output.find("--chunk N"), std::string::npos) << no_chunk.output;
    const auto no_task = test::run_linework("farm task " + test::quote(dir) + " frames 0");
    EXPECT_EQ(no_task.exit_code, 1);
    EXPECT_NE(no_task.output.find("plan.json: no farm plan here"), std::string::npos) << no_task.output;
    const auto no_plan = test::run_linework("farm status " + test::quote(dir));
    EXPECT_EQ(no_plan.exit_code, 1);
    EXPECT_NE(no_plan.output.find("plan.json: no farm plan here"), std::string::npos) << no_plan.output;
    const auto lonely = test::run_linework("render " + kShot + " --frames 0:9 --state-only");
    EXPECT_EQ(lonely.exit_code, 2);
    EXPECT_NE(lonely.output.find("--state-only writes nothing but the states"), std::string::npos) << lonely.output;
    const auto outside = test::run_linework("render " + kShot + " --frames 0:9 --part 5:12 -o " + test::quote(dir / "o"));
    EXPECT_EQ(outside.exit_code, 2);
    EXPECT_NE(outside.output.find("--part 5:12 lies outside the range 0:9"), std::string::npos) << outside.output;

    // A state saved with other options, or for another frame, is refused naming the file.
    ASSERT_EQ(test::run_linework("render " + kShot + " --frames 0:9 --state-only --save-states " +
                                 test::quote(dir / "s") + " --chunk 5")
                  .exit_code,
              0);
    const std::string state = test::quote(dir / "s/state_0005.lwstate");
    const auto other = test::run_linework("render " + kShot + " --frames 0:9 --hidden dashed --part 5:9 -o " +
                                          test::quote(dir / "o") + " --start-state " + state);
    EXPECT_EQ(other.exit_code, 1);
    EXPECT_NE(other.output.find("state_0005.lwstate: saved by a render with other options"), std::string::npos)
        << other.output;
    EXPECT_NE(other.output.find("(--hidden dashed is given now, not then;"), std::string::npos) << other.output;
    const auto wrong = test::run_linework("render " + kShot + " --frames 0:9 --part 6:9 -o " + test::quote(dir / "o") +
                                          " --start-state " + state);
    EXPECT_EQ(wrong.exit_code, 1);
    EXPECT_NE(wrong.output.find("holds the state after frame 4, but this part starts at frame 6"), std::string::npos)
        << wrong.output;
}

}  // namespace
}  // namespace lw
