#include "render_output.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>

#include "commands.h"
#include "io/image_io.h"
#include "lines/visibility.h"
#include "render_options.h"
#include "render_state.h"

namespace lw::cli {

FrameRange parse_frames(const std::string& text, const std::string& option) {
    FrameRange range;
    const auto colon = text.find(':');
    try {
        size_t used = 0;
        if (colon == std::string::npos) {
            range.first = range.last = std::stoi(text, &used);
            if (used != text.size()) throw 0;
        } else {
            range.first = std::stoi(text.substr(0, colon), &used);
            if (used != colon) throw 0;
            range.last = std::stoi(text.substr(colon + 1), &used);
            if (used != text.size() - colon - 1) throw 0;
        }
    } catch (...) {
        throw usage_error(option + ": expected A:B (inclusive) or N, got \"" + text + "\"");
    }
    if (range.last < range.first) throw usage_error(option + ": " + text + " ends before it starts");
    // Frame N is written as frame_NNNN: a negative one would be frame_-005, which image
    // sequence tools read as no frame number at all.
    if (range.first < 0) throw usage_error(option + ": " + text + ": frames are numbered from 0");
    return range;
}

std::filesystem::path svg_path(const FrameFiles& files, int f) {
    std::filesystem::path svg(files.svg);
    if (files.sequence) svg = svg.parent_path() / (svg.stem().string() + "_" + frame_name(f, "svg").substr(6));
    return svg;
}

bool frame_written(const FrameFiles& files, int f) {
    // The PNG is written last (write_frame_files), but each file may have been removed since.
    const auto there = [](const std::filesystem::path& file) {
        std::error_code ec;
        return std::filesystem::is_regular_file(file, ec);
    };
    return there(files.out_dir / frame_name(f, "png")) && (!files.exr || there(files.out_dir / frame_name(f, "exr"))) &&
           (files.svg.empty() || there(svg_path(files, f))) &&
           (files.dump_paths.empty() || there(std::filesystem::path(files.dump_paths) / frame_name(f, "json")));
}

void create_folders(const FrameFiles& files) {
    if (!files.out_dir.empty()) create_folder(files.out_dir, "output");
    if (!files.dump_paths.empty()) create_folder(files.dump_paths, "dump");
    // The SVG's folder too, before the first frame: a missing one would fail only after it.
    if (const auto svg = std::filesystem::path(files.svg).parent_path(); !svg.empty()) create_folder(svg, "SVG");
}

void write_frame_files(const FrameFiles& files, const SceneSession& session, const Frame& frame, int f) {
    const SceneDesc& desc = session.desc();
    if (files.exr)
        write_atomically(files.out_dir / frame_name(f, "exr"), [&](const std::filesystem::path& file) {
            // Z as compositing reads it: eye depth (scene units), the largest float where nothing
            // was drawn (an infinity upsets some compositors' depth filters).
            std::vector<float> z(frame.image.depth.size());
            for (size_t p = 0; p < z.size(); ++p)
                z[p] = std::min(linear_depth(frame.image.depth[p], frame.image.znear, frame.image.zfar),
                                std::numeric_limits<float>::max());
            write_exr(file, frame.image.color, z);
        });
    if (!files.svg.empty())
        write_atomically(svg_path(files, f), [&](const std::filesystem::path& file) {
            write_lines_svg(file, desc.width, desc.height, session.svg_groups(frame));
        });
    if (!files.dump_paths.empty())
        write_text_atomically(std::filesystem::path(files.dump_paths) / frame_name(f, "json"),
                              path_dump_json(f, desc.width, desc.height, session.dump_groups(frame), frame.layers));
    write_atomically(files.out_dir / frame_name(f, "png"),
                     [&](const std::filesystem::path& file) { write_png(file, straight_alpha(frame.image.color)); });
}

void print_frame_report(const FrameFiles& files, const SceneSession& session, const Frame& frame, int f) {
    std::printf("frame %d: %.2f ms", f, frame.timings.total_ms);
    for (const PassTime& t : frame.timings.gpu)
        if (t.ms >= 0.0) std::printf(" (GPU %s %.3f ms)", t.name.c_str(), t.ms);
    std::printf("\n");
    if (session.desc().lines.enabled && session.has_model()) {
        size_t visible = 0;
        for (const auto& p : frame.screen_paths) visible += p.visible;
        std::printf("lines: %zu segments, %zu paths, %zu visible runs (chain %.2f ms, visibility %.2f ms)\n",
                    frame.segments.size(), frame.paths.size(), visible, frame.timings.chain_ms,
                    frame.timings.visibility_ms);
    }
    for (const SceneSession::RibbonReport& r : session.ribbon_reports())
        std::printf("ribbons (%s): %zu paths in %.0f ms, %zu too short\n", r.line_set.c_str(), r.stats.paths, r.stats.ms,
                    r.stats.skipped);
    std::printf("wrote %s\n", (files.out_dir / frame_name(f, "png")).string().c_str());
    if (files.exr) std::printf("wrote %s\n", (files.out_dir / frame_name(f, "exr")).string().c_str());
    if (!files.svg.empty()) std::printf("wrote %s\n", files.svg.c_str());
}

int interrupted(int frame, int first) {
    std::fflush(stdout);
    if (frame >= first)
        std::fprintf(stderr, "\nlinework: interrupted after frame %d (written); run the same command with --resume to go on\n",
                     frame);
    else
        std::fprintf(stderr, "\nlinework: interrupted during the warm-up frames; nothing written\n");
    return 130;
}

void restore_render_state(SceneSession& session, const RenderState& state, FrameRange range) {
    session.restore({frame_time(state.frame, range, session.desc().animation.fps).seconds, state.snapshot});
}

// --resume: the first frame still to render (the state restored), or past the range. The
// state is written after each frame's PNG (and once before the part's first frame), so a
// render killed between the two leaves it one frame behind: that frame is drawn again.
std::optional<int> resume_point(const std::string& signature, const FrameFiles& files, FrameRange range,
                                FrameRange part, SceneSession& session) {
    int first_missing = part.first;
    while (first_missing <= part.last && frame_written(files, first_missing)) ++first_missing;
    if (first_missing == part.first) return std::nullopt;
    if (!files.sequence) return first_missing;  // one still frame: no state to go on from
    const std::filesystem::path& state_path = files.progress_state;
    // Frames there by another command (other options) are not this render's: even when
    // every frame is there, the state says whose they are; frames with no state, whoever
    // wrote them, are not taken as this render's either.
    if (!std::filesystem::exists(state_path))
        throw Error(state_path.string() + ": no render state to resume from (frames " + std::to_string(part.first) +
                    " to " + std::to_string(first_missing - 1) +
                    " are there, but no state says which render wrote them): render without --resume to draw the "
                    "range again");
    const RenderState state = read_render_state(state_path);
    if (state.signature != signature)
        throw Error(state_path.string() + ": written by a render with other options or inputs (" +
                    signature_difference(state.signature, signature) +
                    "; every option but --resume counts, and so do the contents of the scene and the files it names): "
                    "give the options and files that render had, with --resume, or remove the file to start over");
    if (first_missing > part.last) return first_missing;
    if (state.frame != first_missing - 1 && state.frame != first_missing - 2)
        throw Error(state_path.string() + ": holds the state after frame " + std::to_string(state.frame) +
                    ", but the first missing frame is " + std::to_string(first_missing) +
                    " (removed after the render went past it?), and the state to go on from there is gone: remove "
                    "the file to render the range again, or draw the missing frames with --part and --warmup K "
                    "(coherent after K frames)");
    restore_render_state(session, state, range);
    const int start = state.frame + 1;
    if (start < first_missing)
        std::printf("resuming at frame %d (drawn again: it was written, its state was not)\n", start);
    else
        std::printf("resuming at frame %d (frames %d to %d already written)\n", start, part.first, start - 1);
    return start;
}

}  // namespace lw::cli
