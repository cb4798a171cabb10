// Offline renders: Ctrl-C stops after the frame in hand, --resume goes on from the saved
// parameterization and gives the frames of an unbroken run (also when the last frame's
// state was lost to a kill); nothing is left half-written.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/image.h"
#include "io/image_io.h"
#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

TEST(Resume, InterruptedAndResumedSequenceEqualsAnUnbrokenOne) {
    const fs::path dir = test::temp_dir();
    const int last = 23;
    const std::string args = test::quote(test::data_dir() / "models/spot/spot.glb") +
                             " --device cpu --size 160x120 --frames 0:" + std::to_string(last) +
                             " --orbit 90 --slam " + test::quote(test::source_dir() / "scenes/slams/dots.exr");
    const auto whole = test::run_linework("render " + args + " -o " + test::quote(dir / "whole"));
    ASSERT_EQ(whole.exit_code, 0) << whole.output;

    // Interrupt once frame 2 is on disk (a real SIGINT to the running process).
    const fs::path broken = dir / "broken";
    const std::string exe = LW_LINEWORK_EXE;
    const std::string script = "LINEWORK_VALIDATION=1 '" + exe + "' render " + args + " -o " + test::quote(broken) +
                               " > /dev/null 2>&1 & pid=$!; while [ ! -f " + test::quote(broken / test::frame_png(2)) +
                               " ]; do sleep 0.01; if ! kill -0 $pid 2>/dev/null; then break; fi; done; "
                               "kill -INT $pid; wait $pid; echo $?";
    FILE* pipe = popen(script.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    char buffer[64] = {};
    ASSERT_NE(fgets(buffer, sizeof(buffer), pipe), nullptr);
    pclose(pipe);
    ASSERT_EQ(std::string(buffer), "130\n") << "the render was not interrupted (exit " << buffer << ")";
    int written = 0;
    while (fs::exists(broken / test::frame_png(written))) ++written;
    ASSERT_LT(written, last + 1) << "every frame was written before the interrupt arrived";
    EXPECT_GE(written, 3);
    for (const auto& entry : fs::directory_iterator(broken))
        EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();

    const fs::path interrupted_state = dir / "interrupted-state";
    fs::copy_file(broken / ".linework-state", interrupted_state);
    const auto resumed = test::run_linework("render " + args + " -o " + test::quote(broken) + " --resume");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("resuming at frame " + std::to_string(written) + " (frames 0 to"), std::string::npos)
        << resumed.output;
    const auto same_as_whole = [&] {
        for (int f = 0; f <= last; ++f) {
            const ImageRGBA8 a = read_image_rgba8(dir / "whole" / test::frame_png(f));
            const ImageRGBA8 b = read_image_rgba8(broken / test::frame_png(f));
            EXPECT_TRUE(a.pixels == b.pixels) << "frame " << f << " differs from the unbroken run";
        }
    };
    same_as_whole();

    // A render killed after a frame's PNG and before its state (SIGKILL between the two
    // renames) leaves the state one frame behind: that frame is drawn again.
    for (int f = written + 1; f <= last; ++f) fs::remove(broken / test::frame_png(f));
    fs::copy_file(interrupted_state, broken / ".linework-state", fs::copy_options::overwrite_existing);
    const auto lagging = test::run_linework("render " + args + " -o " + test::quote(broken) + " --resume");
    ASSERT_EQ(lagging.exit_code, 0) << lagging.output;
    EXPECT_NE(lagging.output.find("resuming at frame " + std::to_string(written) + " (drawn again"), std::string::npos)
        << lagging.output;
    same_as_whole();

    // Resuming with other options is refused, naming the state file.
    fs::remove(broken / test::frame_png(last));
    std::string other_args = args;
    other_args.replace(other_args.find("--orbit 90"), 10, "--orbit 45");
    const auto other = test::run_linework("render " + other_args + " -o " + test::quote(broken) + " --resume");
    EXPECT_EQ(other.exit_code, 1) << other.output;
    EXPECT_NE(other.output.find(".linework-state: written by a render with other options"), std::string::npos)
        << other.output;
    EXPECT_NE(other.output.find("--orbit was 90 then, 45 now"), std::string::npos) << other.output;
}

// The options name the scene file, not what is in it: a scene edited between the interrupted
// render and its resume (or between a farm's state phase and its chunks) is refused, naming
// the file, instead of drawing on from frames of the scene as it was. The SLAM a key names
// counts as well.
TEST(Resume, AnEditedSceneOrSlamIsNotResumed) {
    const fs::path dir = test::temp_dir();
    fs::copy_file(test::source_dir() / "scenes/slams/dots.exr", dir / "dots.exr");
    const auto write_scene = [&](const std::string& eye) {
        std::ofstream(dir / "shot.json") << R"({"model": ")" << (test::data_dir() / "models/spot/spot.glb").string()
                                         << R"(", "size": [96, 72], "camera": {"eye": )" << eye
                                         << R"(, "target": [0, 0, 0], "orbit": 90},
            "lines": {"silhouette": {"slam": "dots.exr"}}, "animation": {"frames": [0, 3]}})";
    };
    write_scene("[2.6, 0.9, -2.4]");
    const std::string render = "render " + test::quote(dir / "shot.json") + " --device cpu -o " + test::quote(dir / "o");
    ASSERT_EQ(test::run_linework(render).exit_code, 0);
    // Unchanged, every frame is there already (the state says whose they are).
    const auto same = test::run_linework(render + " --resume");
    ASSERT_EQ(same.exit_code, 0) << same.output;
    EXPECT_NE(same.output.find("all frames 0 to 3 are already in"), std::string::npos) << same.output;

    write_scene("[2.7, 0.9, -2.4]");
    const auto edited = test::run_linework(render + " --resume");
    EXPECT_EQ(edited.exit_code, 1) << edited.output;
    EXPECT_NE(edited.output.find(".linework-state: written by a render with other options or inputs ("), std::string::npos)
        << edited.output;
    EXPECT_NE(edited.output.find("shot.json has changed since"), std::string::npos) << edited.output;

    write_scene("[2.6, 0.9, -2.4]");  // as it was: resumes again
    std::ofstream(dir / "dots.exr", std::ios::app) << '\0';
    const auto slam = test::run_linework(render + " --resume");
    EXPECT_EQ(slam.exit_code, 1) << slam.output;
    EXPECT_NE(slam.output.find("dots.exr has changed since"), std::string::npos) << slam.output;
}

// What --resume takes as written: every file the command writes for a frame (not the PNG
// alone), frames that a state speaks for (not frames with none, nor a folder a still frame was
// drawn into since), whatever the spelling of the folders' names.
TEST(Resume, OnlyWholeFramesOfThisRenderAreSkipped) {
    const fs::path dir = test::temp_dir();
    const std::string shot = test::quote(test::data_dir() / "models/spot/spot.glb") +
                             " --device cpu --size 96x72 --frames 0:3 --orbit 30 --dump-paths " + test::quote(dir / "d");
    ASSERT_EQ(test::run_linework("render " + shot + " -o " + test::quote(dir / "o")).exit_code, 0);
    // The same folders spelled another way are the same render.
    const auto spelled = test::run_linework("render " + shot + "/ -o " + test::quote(dir / "x/../o/") + " --resume");
    EXPECT_EQ(spelled.exit_code, 0) << spelled.output;
    EXPECT_NE(spelled.output.find("all frames 0 to 3 are already in"), std::string::npos) << spelled.output;
    // A relative folder the first render made is the same folder to its resume (before the
    // folder existed its name could not be made absolute the same way, and every resume of a
    // new relative -o was refused).
    const std::string in_dir = "cd " + test::quote(dir) + " && LINEWORK_VALIDATION=1 '" + std::string(LW_LINEWORK_EXE) +
                               "' render " + test::quote(test::data_dir() / "models/spot/spot.glb") +
                               " --device cpu --size 96x72 --frames 0:1 -o rel --dump-paths reld";
    ASSERT_EQ(test::run_command(in_dir + " > /dev/null 2>&1").exit_code, 0);
    const auto relative = test::run_command(in_dir + " --resume 2>&1");
    EXPECT_EQ(relative.exit_code, 0) << relative.output;
    EXPECT_NE(relative.output.find("all frames 0 to 1 are already in rel"), std::string::npos) << relative.output;
    // A frame whose dump is gone is not written: here the state has gone past it.
    fs::remove(dir / "d/frame_0001.json");
    const auto dump_gone = test::run_linework("render " + shot + " -o " + test::quote(dir / "o") + " --resume");
    EXPECT_EQ(dump_gone.exit_code, 1) << dump_gone.output;
    EXPECT_NE(dump_gone.output.find("the first missing frame is 1"), std::string::npos) << dump_gone.output;
    // Every frame there but no state: nothing says which render wrote them.
    ASSERT_EQ(test::run_linework("render " + shot + " -o " + test::quote(dir / "o")).exit_code, 0);
    fs::remove(dir / "o/.linework-state");
    const auto no_state = test::run_linework("render " + shot + " -o " + test::quote(dir / "o") + " --resume");
    EXPECT_EQ(no_state.exit_code, 1) << no_state.output;
    EXPECT_NE(no_state.output.find(".linework-state: no render state to resume from (frames 0 to 3 are there, but no "
                                   "state says which render wrote them)"),
              std::string::npos)
        << no_state.output;
    // A still frame drawn into the folder takes the sequence's state away with it.
    ASSERT_EQ(test::run_linework("render " + shot + " -o " + test::quote(dir / "o")).exit_code, 0);
    ASSERT_EQ(test::run_linework("render " + test::quote(test::data_dir() / "models/spot/spot.glb") +
                                 " --device cpu --size 48x36 -o " + test::quote(dir / "o"))
                  .exit_code,
              0);
    EXPECT_FALSE(fs::exists(dir / "o/.linework-state"));
    EXPECT_EQ(test::run_linework("render " + shot + " -o " + test::quote(dir / "o") + " --resume").exit_code, 1);
}

// A second Ctrl-C does not wait for the frame in hand: a ribbon style can take minutes a
// frame (here a 1024-texel exemplar along a drawing's strokes), and the first Ctrl-C only
// asks for a stop after it. The process dies of the signal, with nothing written.
TEST(Resume, ASecondInterruptStopsAtOnce) {
    const fs::path dir = test::temp_dir();
    ASSERT_EQ(test::run_linework("ribbon-exemplar rope --size 1024x48 -o " + test::quote(dir / "rope.png")).exit_code, 0);
    std::ofstream(dir / "slow.json") << R"({"size": [160, 120], "layers": [{"strokes": ")"
                                     << (test::source_dir() / "scenes/patterns/flowers.svg").string()
                                     << R"(", "ribbon": "rope.png"}]})";
    const std::string exe = LW_LINEWORK_EXE, scene = (dir / "slow.json").string(), out = (dir / "out").string();
    const fs::path log = dir / "log.txt";
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
    std::vector<std::string> args = {exe, "render", scene, "-o", out, "--device", "cpu", "--frames", "0:1"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, exe.c_str(), &files, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&files);
    int status = 0;
    bool ended = false;
    // However the test ends, the render (whose frame takes minutes) does not outlive it.
    struct Reaper {
        pid_t pid;
        bool& ended;
        ~Reaper() {
            if (ended) return;
            kill(pid, SIGKILL);
            waitpid(pid, nullptr, 0);
        }
    } reaper{pid, ended};

    const auto log_holds = [&](const std::string& text) {
        std::ifstream in(log);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()).find(text) !=
               std::string::npos;
    };
    // Waits up to 60 s for `done`; false if it never came.
    const auto wait_for = [](const auto& done) {
        for (int i = 0; i < 6000; ++i) {
            if (done()) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return false;
    };
    const auto exited = [&] { return ended = ended || waitpid(pid, &status, WNOHANG) == pid; };
    ASSERT_TRUE(wait_for([&] { return log_holds("size: 160x120") || exited(); }) && !ended)
        << "the render did not start its frame";
    kill(pid, SIGINT);
    ASSERT_TRUE(wait_for([&] { return log_holds("stopping after the frame in hand"); }));
    // (A repeat within 0.3 s is the same stop, delivered twice: the next test.)
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    kill(pid, SIGINT);
    ASSERT_TRUE(wait_for(exited)) << "the render went on after a second Ctrl-C";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT);
    EXPECT_FALSE(fs::exists(out + "/frame_0000.png"));
    EXPECT_TRUE(log_holds("stopped at once; the frames written are whole; run the same command with --resume"));
}

// One stop delivered twice at once (a kill of a whole process tree or cgroup reaches a farm
// task's render directly and through the task) is one stop: the frame in hand is finished
// and written, and the render exits 130 rather than dying of the signal.
TEST(Resume, TheSameStopTwiceAtOnceFinishesTheFrame) {
    const fs::path dir = test::temp_dir();
    const std::string exe = LW_LINEWORK_EXE;
    const fs::path out = dir / "out";
    const auto r = test::run_command(
        "LINEWORK_VALIDATION=1 '" + exe + "' render " + test::quote(test::data_dir() / "models/spot/spot.glb") +
        " --device cpu --size 64x48 --frames 0:999 -o " + test::quote(out) +
        " > /dev/null 2>&1 & pid=$!; i=0; while [ ! -f " + test::quote(out / test::frame_png(2)) +
        " ] && [ $i -lt 6000 ]; do sleep 0.01; i=$((i + 1)); done; kill -TERM $pid; kill -TERM $pid; wait $pid; echo $?");
    EXPECT_EQ(r.output, "130\n");
    int written = 0;
    while (fs::exists(out / test::frame_png(written))) ++written;
    EXPECT_GE(written, 3);
    EXPECT_LT(written, 1000);
}

// A still camera on a dense model: the paths kept from frame to frame (still_paths.h) travel
// in the saved state, so a part started from it gives the unbroken run's paths, and the same
// render saves the same state bytes (no padding written).
TEST(Resume, AStillShotStartedFromItsStateEqualsAnUnbrokenOne) {
    const fs::path dir = test::temp_dir();
    // --dump-paths is part of what a state is saved with (every set is parameterized), but not
    // its folder: each run dumps to its own.
    const std::string args = test::quote(test::data_dir() / "models/FlightHelmet/FlightHelmet.gltf") +
                             " --device cpu --size 160x120 --frames 0:7 --slam " +
                             test::quote(test::source_dir() / "scenes/slams/dots.exr");
    for (const char* states : {"s1", "s2"})
        ASSERT_EQ(test::run_linework("render " + args + " --state-only --chunk 4 --save-states " +
                                     test::quote(dir / states) + " --dump-paths " + test::quote(dir / states / "dump"))
                      .exit_code,
                  0);
    const auto bytes = [](const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    const std::string state = bytes(dir / "s1/state_0004.lwstate");
    EXPECT_GT(state.size(), 1000u);
    EXPECT_TRUE(state == bytes(dir / "s2/state_0004.lwstate"));

    const auto whole = test::run_linework("render " + args + " -o " + test::quote(dir / "whole") + " --dump-paths " +
                                          test::quote(dir / "whole_dump"));
    ASSERT_EQ(whole.exit_code, 0) << whole.output;
    const auto part = test::run_linework("render " + args + " --part 4:7 -o " + test::quote(dir / "part") +
                                         " --dump-paths " + test::quote(dir / "dump") + " --start-state " +
                                         test::quote(dir / "s1/state_0004.lwstate"));
    ASSERT_EQ(part.exit_code, 0) << part.output;
    for (int f = 4; f <= 7; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.json", f);
        const std::string expected = bytes(dir / "whole_dump" / name);
        EXPECT_GT(expected.size(), 1000u) << name;
        EXPECT_TRUE(bytes(dir / "dump" / name) == expected) << name;
    }
}

// An animated model's lines do not depend on the frame a render starts at: the line mesh (its
// weld, feature size and crease edges) is built in the pose at 0 s, so frame 3 of the Fox's
// run drawn alone, or as a part, is frame 3 of the sequence, pixel for pixel. Built in the
// first frame drawn, it differed in 0.97 % of the pixels (creases of another pose).
TEST(Resume, AnAnimatedFrameDrawnAloneEqualsItsFrameInTheSequence) {
    const fs::path dir = test::temp_dir();
    std::ofstream(dir / "fox.json") << R"({"model": ")" << (test::data_dir() / "models/Fox/Fox.glb").string() << R"(",
        "camera": {"eye": [191.75, 106.5, 142.66], "target": [0, 39.39, -10.74]},
        "animation": {"clip": "Run", "fps": 24, "frames": [0, 11]}})";
    const std::string args = test::quote(dir / "fox.json") + " --device cpu --size 240x180 --lines-only";
    struct Run {
        const char *name, *frames;
    };
    for (const Run run : {Run{"sequence", "--frames 0:3"}, Run{"alone", "--frames 3:3"}, Run{"part", "--frames 0:5 --part 3:5"}}) {
        const auto r = test::run_linework("render " + args + " " + run.frames + " -o " + test::quote(dir / run.name));
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    const ImageRGBA8 sequence = read_image_rgba8(dir / "sequence" / test::frame_png(3));
    size_t inked = 0;
    for (size_t i = 0; i < sequence.pixels.size(); i += 4) inked += sequence.pixels[i] < 128;
    EXPECT_GT(inked, 500u);
    for (const char* other : {"alone", "part"})
        EXPECT_TRUE(read_image_rgba8(dir / other / test::frame_png(3)).pixels == sequence.pixels) << other;
}

// A part of a parameterized shot rendered without a state starts its strokes afresh, unlike
// the same frames of one render: said. Plain lines carry nothing from frame to frame: silent.
TEST(Resume, APartWithoutItsStateSaysItStartsAfresh) {
    const fs::path dir = test::temp_dir();
    const std::string spot = test::quote(test::data_dir() / "models/spot/spot.glb") +
                             " --device cpu --size 64x48 --frames 0:3 --part 2:3 --orbit 10 -o " + test::quote(dir / "out");
    auto r = test::run_linework("render " + spot + " --slam " + test::quote(test::source_dir() / "scenes/slams/dots.exr"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("warning: --part 2:3 without --start-state or --warmup: the strokes' parameterization "
                            "starts afresh at frame 2"),
              std::string::npos)
        << r.output;
    r = test::run_linework("render " + spot);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace lw
