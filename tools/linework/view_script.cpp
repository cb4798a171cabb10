#include "view_script.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/image.h"
#include "core/text.h"
#include "view_keys.h"

namespace lw::cli {

namespace {

float number(const std::string& word, const std::string& where) {
    try {
        size_t used = 0;
        const float v = std::stof(word, &used);
        if (used == word.size() && std::isfinite(v)) return v;
    } catch (...) {
    }
    throw Error(where + ": expected a number, got \"" + word + "\"");
}

}  // namespace

std::vector<ScriptCommand> parse_script(const std::string& text, const std::string& source) {
    using Kind = ScriptCommand::Kind;
    std::vector<ScriptCommand> commands;
    std::istringstream lines(text);
    std::string line;
    for (int n = 1; std::getline(lines, line); ++n) {
        std::istringstream words(line);
        std::vector<std::string> w;
        // `#` starts a comment, on a line of its own or after a command.
        for (std::string word; words >> word && word[0] != '#';) w.push_back(word);
        if (w.empty()) continue;
        const std::string where = source + ":" + std::to_string(n) + ": " + w[0];
        auto args = [&](size_t count) {
            if (w.size() != count + 1)
                throw Error(where + ": expected " + std::to_string(count) + " argument(s), got " + std::to_string(w.size() - 1));
        };
        ScriptCommand c{.line = n};
        const std::string& op = w[0];
        if (op == "wait") {
            args(1);
            c.kind = Kind::Wait;
            c.a = number(w[1], where);
            if (c.a < 0 || c.a != std::floor(c.a)) throw Error(where + ": frames must be a whole number ≥ 0");
        } else if (op == "orbit" || op == "pan") {
            args(2);
            c.kind = op == "orbit" ? Kind::Orbit : Kind::Pan;
            c.a = number(w[1], where);
            c.b = number(w[2], where);
        } else if (op == "zoom") {
            args(1);
            c.kind = Kind::Zoom;
            c.a = number(w[1], where);
            if (!(c.a > 0.0f)) throw Error(where + ": the factor must be greater than 0");
        } else if (op == "key") {
            args(1);
            c.kind = Kind::Key;
            c.text = w[1];
            if (key_from_name(c.text) < 0) throw Error(where + ": unknown key \"" + c.text + "\" (" + key_names() + ")");
        } else if (op == "resize") {
            args(2);
            c.kind = Kind::Resize;
            c.a = number(w[1], where);
            c.b = number(w[2], where);
            const double largest = kLargestImageSide;
            if (c.a < 1 || c.b < 1 || c.a > largest || c.b > largest || c.a != std::floor(c.a) || c.b != std::floor(c.b))
                throw Error(where + ": width and height must be whole numbers 1.." + std::to_string(kLargestImageSide));
        } else if (op == "minimize" || op == "restore" || op == "quit") {
            args(0);
            c.kind = op == "minimize" ? Kind::Minimize : op == "restore" ? Kind::Restore : Kind::Quit;
        } else if (op == "screenshot" || op == "save") {
            args(1);
            c.kind = op == "screenshot" ? Kind::Screenshot : Kind::Save;
            c.text = w[1];
        } else {
            throw Error(source + ":" + std::to_string(n) + ": unknown command \"" + op +
                        "\" (wait, orbit, zoom, pan, key, resize, minimize, restore, screenshot, save, quit)");
        }
        commands.push_back(std::move(c));
    }
    return commands;
}

std::vector<ScriptCommand> read_script(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw Error(path.string() + ": not a regular file (a script is a text file of commands)");
    if (const std::string ext = lower(path.extension().string()); ext == ".png" || ext == ".exr" || ext == ".json")
        throw Error(path.string() + ": a script is a text file of commands, not a" + (ext == ".json" ? " JSON" : "n image") +
                    " file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot open script");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return parse_script(buffer.str(), path.string());
}

std::vector<ScriptCommand> ScriptPlayer::next_frame() {
    std::vector<ScriptCommand> now;
    if (waiting_ > 0) {
        --waiting_;
        return now;
    }
    while (next_ < commands_.size()) {
        const ScriptCommand& c = commands_[next_++];
        if (c.kind == ScriptCommand::Kind::Wait) {
            if (c.a >= 1.0f) {
                waiting_ = long(c.a) - 1;  // this frame is the first of the wait
                break;
            }
            continue;
        }
        now.push_back(c);
        if (c.kind == ScriptCommand::Kind::Screenshot || c.kind == ScriptCommand::Kind::Quit) break;
    }
    return now;
}

}  // namespace lw::cli
