// tests/test_viewer.cpp — `linework view` under Xvfb: a scripted session, its golden image,
// the same pixels as `linework render`, resizing and minimizing; the script language and
// the saved view's scene JSON.
//
// The window tests run `xvfb-run` (package xvfb) with LINEWORK_VALIDATION=1 on lavapipe;
// they are skipped, with the reason, when xvfb-run is not installed. Golden image:
// regenerate with LINEWORK_UPDATE_GOLDENS=1 ctest --test-dir build -R Viewer
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/image.h"
#include "io/image_io.h"
#include "scene/scene_file.h"
#include "test_support.h"
#include "../tools/linework/view_script.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

bool have_xvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// `linework view ARGS` in a fresh X server, validation on.
test::CommandResult run_view(const std::string& args) {
    return test::run_command("LINEWORK_VALIDATION=1 xvfb-run -a -s '-screen 0 1280x1024x24' '" +
                             std::string(LW_LINEWORK_EXE) + "' view " + args + " --device cpu 2>&1");
}

void write_file(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// PSNR ≥ 40 dB and at most 0.5 % of pixels off by more than 16 levels (tests/test_render.cpp).
void expect_close(const ImageRGBA8& actual, const ImageRGBA8& expected, const fs::path& out, const char* what) {
    ASSERT_EQ(actual.width, expected.width) << what;
    ASSERT_EQ(actual.height, expected.height) << what;
    const ImageDiff d = compare_images(actual, expected, 16);
    EXPECT_GE(d.psnr_db, 40.0) << what;
    EXPECT_LE(d.differing_fraction, 0.005) << what;
    if (d.psnr_db < 40.0 || d.differing_fraction > 0.005) {
        write_png(out / "diff.png", d.diff);
        ADD_FAILURE() << what << ": diff written to " << out / "diff.png";
    }
}

TEST(ViewerScript, ParsesAndPlaysFrameByFrame) {
    using Kind = cli::ScriptCommand::Kind;
    const auto commands = cli::parse_script("# a comment\n\norbit 10 -5  # after a command too\nzoom 2\nwait 3\nkey s\nscreenshot a.png\n"
                                            "key F1\nresize 640 480\nminimize\nrestore\nquit\n",
                                            "s.txt");
    ASSERT_EQ(commands.size(), 10u);
    EXPECT_EQ(commands[0].kind, Kind::Orbit);
    EXPECT_FLOAT_EQ(commands[0].b, -5.0f);
    EXPECT_EQ(commands[0].line, 3);
    cli::ScriptPlayer player(commands);
    EXPECT_EQ(player.next_frame().size(), 2u);  // orbit, zoom; then wait 3 (this frame and two more)
    EXPECT_TRUE(player.next_frame().empty());
    EXPECT_TRUE(player.next_frame().empty());
    const auto third = player.next_frame();      // key s, screenshot: a screenshot ends the frame
    ASSERT_EQ(third.size(), 2u);
    EXPECT_EQ(third[1].kind, Kind::Screenshot);
    EXPECT_EQ(player.next_frame().size(), 5u);   // key F1 … quit
    EXPECT_TRUE(player.finished());

    for (const char* bad : {"orbit 1", "zoom 0", "zoom x", "key nosuchkey", "resize 0 10", "wait 1.5", "jump 3"}) {
        try {
            (void)cli::parse_script(std::string("wait 1\n") + bad + "\n", "bad.txt");
            ADD_FAILURE() << "accepted: " << bad;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("bad.txt:2:"), std::string::npos) << e.what();
        }
    }
}

TEST(ViewerScene, SavedViewReadsBack) {
    SceneDesc desc = scene_for_model(test::data_dir() / "models/spot/spot.glb");
    desc.width = 400;
    desc.height = 300;
    desc.style.shading = Shading::Flat;
    desc.lines.params.suggestive = false;
    desc.lines.params.sug_thresh = 0.05f;
    desc.lines.params.crease_angle_deg = 30.0f;
    desc.lines.styles[2].width = 3.0f;
    desc.lines.sample_spacing_px = 3.0f;
    const ViewCamera camera{.eye = {1, 2, 3}, .target = {0, 0.5f, 0}, .fov_deg = 35.0f};
    const fs::path dir = test::temp_dir();
    const SceneDesc back = parse_scene_json(scene_json(desc, camera, dir), dir / "view.json");
    ASSERT_EQ(back.models.size(), 1u);
    EXPECT_TRUE(fs::equivalent(back.models[0], desc.models[0]));
    EXPECT_EQ(back.width, 400);
    ASSERT_TRUE(back.camera.has_value());
    EXPECT_EQ(back.camera->eye, camera.eye);
    EXPECT_FLOAT_EQ(back.camera->fov_deg, 35.0f);
    EXPECT_EQ(back.style.shading, Shading::Flat);
    EXPECT_FALSE(back.lines.params.suggestive);
    EXPECT_TRUE(back.lines.params.silhouettes);
    EXPECT_FLOAT_EQ(back.lines.params.sug_thresh, 0.05f);
    EXPECT_FLOAT_EQ(back.lines.params.crease_angle_deg, 30.0f);
    EXPECT_FLOAT_EQ(back.lines.styles[2].width, 3.0f);
    EXPECT_FLOAT_EQ(back.lines.sample_spacing_px, 3.0f);
}

// Opens the window, orbits, turns suggestive contours off and on, takes a screenshot (the
// panel hidden with F1) that matches the golden image and `linework render` of the saved
// view — the same renderer — and exits cleanly with the validation layer silent.
TEST(Viewer, ScriptedSessionMatchesGoldenAndRender) {
    if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed (apt-get install xvfb xauth)";
    const fs::path dir = test::temp_dir();
    write_file(dir / "session.txt", "key f1\nwait 2\norbit 30 10\nwait 2\nkey s\nwait 2\nkey s\nwait 2\n"
                                    "screenshot " + (dir / "shot.png").string() + "\nsave " +
                                        (dir / "view.json").string() + "\nquit\n");
    const auto r = run_view(test::quote(test::data_dir() / "models/spot/spot.glb") + " --size 320x240 --script " +
                            test::quote(dir / "session.txt"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find("validation:"), std::string::npos) << r.output;
    const ImageRGBA8 shot = read_image_rgba8(dir / "shot.png");
    EXPECT_EQ(shot.width, 320);
    EXPECT_EQ(shot.height, 240);

    // The saved view rendered headlessly: the same frame.
    const auto rendered = test::run_linework("render " + test::quote(dir / "view.json") + " -o " +
                                             test::quote(dir / "render") + " --device cpu");
    ASSERT_EQ(rendered.exit_code, 0) << rendered.output;
    expect_close(shot, read_image_rgba8(dir / "render/frame_0000.png"), dir, "viewer vs linework render");

    const fs::path golden = test::source_dir() / "tests/golden/view_spot_orbit.png";
    if (const char* update = std::getenv("LINEWORK_UPDATE_GOLDENS"); update && std::string(update) == "1") {
        write_png(golden, shot);
        GTEST_SKIP() << "updated " << golden;
    }
    expect_close(shot, read_image_rgba8(golden), dir, "viewer vs golden");
}

// F12 and F5 write the next numbered file that is not there yet: a file from an earlier
// session is kept, and a screenshot the script names takes no number.
TEST(Viewer, NumberedFilesGoOnAfterThoseThere) {
    if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed (apt-get install xvfb xauth)";
    const fs::path dir = test::temp_dir();
    write_file(dir / "linework_view_0001.png", "an earlier session's");
    write_file(dir / "session.txt", "wait 1\nscreenshot " + (dir / "named.png").string() +
                                        "\nkey f12\nwait 1\nkey f12\nwait 1\nkey f5\nwait 1\nquit\n");
    const auto r = run_view(test::quote(test::data_dir() / "models/spot/spot.glb") + " --size 160x120 -o " +
                            test::quote(dir) + " --script " + test::quote(dir / "session.txt"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(read_image_rgba8(dir / "named.png").width, 160);
    EXPECT_EQ(read_image_rgba8(dir / "linework_view_0000.png").width, 160) << r.output;
    std::ifstream kept(dir / "linework_view_0001.png");
    const std::string earlier((std::istreambuf_iterator<char>(kept)), std::istreambuf_iterator<char>());
    EXPECT_EQ(earlier, "an earlier session's");
    EXPECT_EQ(read_image_rgba8(dir / "linework_view_0002.png").width, 160) << r.output;
    EXPECT_FALSE(fs::exists(dir / "linework_view_0003.png"));
    EXPECT_EQ(load_scene_file(dir / "linework_view_0000.json").width, 160) << r.output;
}

// Resizing makes the swapchain again at the new size; minimizing pauses rendering without
// a zero-sized swapchain; the panel is drawn meanwhile; nothing crashes or warns.
TEST(Viewer, ResizeAndMinimizeByScript) {
    if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed (apt-get install xvfb xauth)";
    const fs::path dir = test::temp_dir();
    write_file(dir / "resize.txt", "wait 2\nresize 400 300\nwait 3\nscreenshot " + (dir / "a.png").string() +
                                       "\nminimize\nwait 4\nrestore\nwait 2\nresize 160 360\nwait 3\nkey f1\n"
                                       "screenshot " + (dir / "b.png").string() + "\nresize 1 1\nwait 2\n"
                                       "resize 320 240\nwait 2\nquit\n");
    const auto r = run_view(test::quote(test::data_dir() / "models/spot/spot.glb") + " --size 320x240 --script " +
                            test::quote(dir / "resize.txt"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find("validation:"), std::string::npos) << r.output;
    const ImageRGBA8 a = read_image_rgba8(dir / "a.png"), b = read_image_rgba8(dir / "b.png");
    EXPECT_EQ(a.width, 400);
    EXPECT_EQ(a.height, 300);
    EXPECT_EQ(b.width, 160);
    EXPECT_EQ(b.height, 360);
}

// Viewer parity: a scene of line sets with a ribbon set (synthesized on the host and written
// back to the target the window shows) looks in the viewer as `linework render` draws it, and
// the saved view keeps the sets.
TEST(Viewer, LineSetsAndRibbonsAsRenderDrawsThem) {
    if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed (apt-get install xvfb xauth)";
    const fs::path dir = test::temp_dir();
    // A small beads exemplar (48×16) keeps the host synthesis to seconds a frame.
    const auto exemplar = test::run_linework("ribbon-exemplar beads -o " + test::quote(dir / "beads.png") +
                                             " --size 48x16 --seed 3");
    ASSERT_EQ(exemplar.exit_code, 0) << exemplar.output;
    write_file(dir / "scene.json",
               "{\"model\": \"" + (test::data_dir() / "models/spot/spot.glb").string() +
                   "\", \"size\": [160, 120], \"shading\": \"unlit\", \"color\": [1, 1, 1],"
                   " \"camera\": {\"eye\": [2.6, 0.9, -2.4], \"target\": [0, 0.05, 0], \"fov\": 35},"
                   " \"line_sets\": [{\"name\": \"beads\", \"select\": {\"types\": [\"silhouette\"]},"
                   " \"style\": {\"width\": 10, \"ribbon\": \"" + (dir / "beads.png").string() +
                   "\"}}, {\"name\": \"inner\", \"select\": {\"types\": [\"suggestive\", \"crease\"]},"
                   " \"style\": {\"width\": 2, \"cap\": \"round\", \"color\": [0.6, 0.1, 0.1]}}]}");
    write_file(dir / "session.txt", "key f1\nwait 1\nscreenshot " + (dir / "shot.png").string() + "\nsave " +
                                        (dir / "view.json").string() + "\nquit\n");
    const auto r = run_view(test::quote(dir / "scene.json") + " --script " + test::quote(dir / "session.txt"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find("validation:"), std::string::npos) << r.output;
    const auto rendered = test::run_linework("render " + test::quote(dir / "scene.json") + " -o " +
                                             test::quote(dir / "render") + " --device cpu");
    ASSERT_EQ(rendered.exit_code, 0) << rendered.output;
    const ImageRGBA8 shot = read_image_rgba8(dir / "shot.png");
    const ImageRGBA8 render = read_image_rgba8(dir / "render/frame_0000.png");
    expect_close(shot, render, dir, "viewer vs linework render, with a ribbon set");
    size_t coloured = 0;  // the beads are coloured; the unlit white cow is not
    for (size_t i = 0; i < shot.pixels.size(); i += 4)
        coloured += std::max({shot.pixels[i], shot.pixels[i + 1], shot.pixels[i + 2]}) -
                        std::min({shot.pixels[i], shot.pixels[i + 1], shot.pixels[i + 2]}) > 40;
    EXPECT_GT(coloured, 50u) << "no ribbon in the viewer's frame";
    const SceneDesc saved = load_scene_file(dir / "view.json");
    ASSERT_EQ(saved.lines.sets.size(), 2u);
    EXPECT_EQ(saved.lines.sets[0].name, "beads");
    EXPECT_FALSE(saved.lines.sets[0].style.ribbon.empty());
}

}  // namespace
}  // namespace lw
