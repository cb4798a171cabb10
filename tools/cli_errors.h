// tools/cli_errors.h — CLI11's parse errors as the tools' other messages word them.
//
// CLI11 says "--frames: At Most 1 required but received 2" for a flag given twice, and can
// list arguments it did not expect in reverse order ("320x240 --sizee"). The rest of its
// messages are clear as they are. Shared by `linework` and `linework-bench`.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace lw::cli {

// `app`: the parsed (or failed) application; argv: the command line it was given.
inline std::string parse_error_text(const CLI::ParseError& e, const CLI::App& app, int argc, const char* const* argv) {
    const std::string what = e.what();
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
        const std::string tag = ": At Most 1 required but received ";
        const size_t at = what.find(tag);
        if (at != std::string::npos)
            return what.substr(0, at) + ": given " + what.substr(at + tag.size()) + " times; give it once";
    }
    if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
        // The arguments left over, in the order given (an argument with a space stays whole).
        std::vector<std::string> left = app.remaining(true), given;
        for (int i = 1; i < argc && !left.empty(); ++i)
            if (const auto it = std::find(left.begin(), left.end(), argv[i]); it != left.end()) {
                given.push_back(*it);
                left.erase(it);
            }
        if (!given.empty() && left.empty()) {
            std::string list;
            for (const std::string& a : given)
                list += (list.empty() ? "" : " ") + (a.find(' ') == std::string::npos ? a : "'" + a + "'");
            return "unexpected argument" + std::string(given.size() > 1 ? "s" : "") + " (an unknown option, or a " +
                   "value too many): " + list;
        }
    }
    return what;
}

}  // namespace lw::cli
