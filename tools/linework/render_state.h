// tools/linework/render_state.h — what `linework render --resume` needs to go on where an
// interrupted sequence stopped, and files that are never seen half-written.
//
// OUT/.linework-state (binary, rewritten after every frame; .linework-state-C-D for a
// --part), and a farm's DIR/state_NNNN.lwstate (--save-states): the command's signature
// (its options, so that a different render does not resume from it), the last frame
// drawn, and the coherent parameterization's state after it (FrameRenderer::coherence_snapshot:
// per tracker, the last splat's sprites and camera — tens to hundreds of kB).
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "render/frame_renderer.h"

namespace lw::cli {

struct RenderState {
    std::string signature;
    int frame = 0;              // the last frame drawn: the state is the one after it
    FrameRenderer::CoherenceSnapshot snapshot;
};

void write_render_state(const std::filesystem::path& path, const RenderState& state);
// Throws lw::Error naming the file when it is missing, truncated or not a state file.
[[nodiscard]] RenderState read_render_state(const std::filesystem::path& path);

// Writes through `write(temporary)` (NAME.partial.EXT beside `path`, so that image writers
// still see the extension) and renames the result onto `path`: a reader, or a render killed
// mid-write, never leaves a half-written file under the final name.
void write_atomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);
// Makes `dir` (and its parents); "DIR: cannot create WHAT folder (reason)" otherwise.
void create_folder(const std::filesystem::path& dir, const std::string& what);

// `text` into `path` the same way; errors name the file.
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

// DIR/state_NNNN.lwstate: the state a render of frames NNNN… starts from (--save-states).
[[nodiscard]] std::filesystem::path saved_state_path(const std::filesystem::path& dir, int start);

}  // namespace lw::cli
