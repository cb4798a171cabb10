// tools/linework/render_output.h — what `linework render` writes per frame, and how a frame
// range is given: frame file names, --frames, and the write of one finished frame (PNG
// last, every file through a temporary name; render_state.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "render/frame_renderer.h"
#include "render_state.h"
#include "scene/camera_path.h"
#include "session/scene_session.h"

namespace lw::cli {

// "A:B" (inclusive) or "N" (one frame); a usage error otherwise.
// `option` names the flag in the message.
[[nodiscard]] FrameRange parse_frames(const std::string& text, const std::string& option = "--frames");

struct FrameFiles {
    std::filesystem::path out_dir;
    std::string svg;         // --svg (per frame NAME_NNNN.svg in a sequence)
    std::string dump_paths;  // --dump-paths folder
    bool exr = false;
    bool sequence = false;
    std::filesystem::path progress_state;  // what --resume goes on from (render_state.h)
};

// Frame f's SVG: --svg's name, with _NNNN before the extension in a sequence.
[[nodiscard]] std::filesystem::path svg_path(const FrameFiles& files, int f);

// Whether every file of frame f that `files` asks for is there (the PNG, and the EXR, SVG
// and path dump where asked for): what --resume skips.
[[nodiscard]] bool frame_written(const FrameFiles& files, int f);

// Makes the output folder, the dump folder and the SVG's folder (when asked for); errors
// name them.
void create_folders(const FrameFiles& files);

// Writes the frame's files: EXR, SVG, dump, then the PNG (a frame whose PNG exists is
// complete, which --resume relies on).
void write_frame_files(const FrameFiles& files, const SceneSession& session, const Frame& frame, int f);

// One line per frame of a single-frame render: time, GPU passes, lines, files written.
void print_frame_report(const FrameFiles& files, const SceneSession& session, const Frame& frame, int f);

// The state after frame state.frame into `session`, posed at that frame's time in `range`.
void restore_render_state(SceneSession& session, const RenderState& state, FrameRange range);

// --resume: the first frame of `part` still to render, its state restored into `session`
// from files.progress_state (past the part when every frame is there; nothing when no frame
// of the part is written yet). `signature`: the options that shape the frames; `range`: the
// whole range (the camera path's).
[[nodiscard]] std::optional<int> resume_point(const std::string& signature, const FrameFiles& files, FrameRange range,
                                              FrameRange part, SceneSession& session);

// After Ctrl-C or SIGTERM: says what was written and how to go on (frame < first: nothing
// written); returns 130.
int interrupted(int frame, int first);

}  // namespace lw::cli
