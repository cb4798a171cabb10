// tools/linework/view_script.h — the `linework view --script FILE` language.
//
// One command a line; blank lines and lines starting with '#' are skipped:
//   wait FRAMES        render FRAMES frames before the next command
//   orbit DX DY        turn the camera about its target, degrees (DX > 0: eye to the right,
//                      DY > 0: eye up)
//   zoom F             distance to the target × 1/F (F > 1 comes closer)
//   pan DX DY          move eye and target by DX, DY pixels (right, down)
//   key NAME           press a key (names: view_keys.h, README "linework view")
//   resize W H         resize the window (the swapchain is made again)
//   minimize | restore iconify the window / bring it back (rendering pauses meanwhile)
//   screenshot PATH    write the next presented frame as PNG (ends this frame's commands)
//   save PATH          write the current view as a scene file
//   quit               close the window and exit
// Commands up to a `wait` (or a `screenshot`) apply before the same frame is rendered.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lw::cli {

struct ScriptCommand {
    enum class Kind { Wait, Orbit, Zoom, Pan, Key, Resize, Minimize, Restore, Screenshot, Save, Quit };
    Kind kind = Kind::Wait;
    float a = 0.0f, b = 0.0f;  // numbers of wait, orbit, zoom, pan, resize
    std::string text;          // key name or file path
    int line = 0;              // in the script, for messages
};

// Reads and checks a script; errors name the file and line ("s.txt:3: zoom: ...").
[[nodiscard]] std::vector<ScriptCommand> parse_script(const std::string& text, const std::string& source);
[[nodiscard]] std::vector<ScriptCommand> read_script(const std::filesystem::path& path);

// Hands out the commands frame by frame.
class ScriptPlayer {
public:
    explicit ScriptPlayer(std::vector<ScriptCommand> commands) : commands_(std::move(commands)) {}
    // The commands to apply before this frame is rendered (empty while waiting).
    [[nodiscard]] std::vector<ScriptCommand> next_frame();
    [[nodiscard]] bool finished() const { return next_ >= commands_.size() && waiting_ == 0; }

private:
    std::vector<ScriptCommand> commands_;
    size_t next_ = 0;
    long waiting_ = 0;
};

}  // namespace lw::cli
