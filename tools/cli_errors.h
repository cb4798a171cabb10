// tools/cli_errors.h — CLI11's parse errors as the tools' other messages word them.
//
// CLI11 says "--frames: At Most 1 required but received 2" for a flag given twice, and lists
// arguments it did not expect in reverse order ("320x240 --sizee"). The rest of its messages
// are clear as they are. Shared by `linework` and `linework-bench`.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace lw::cli {

inline std::string parse_error_text(const CLI::ParseError& e) {
    const std::string what = e.what();
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
        const std::string tag = ": At Most 1 required but received ";
        const size_t at = what.find(tag);
        if (at != std::string::npos)
            return what.substr(0, at) + ": given " + what.substr(at + tag.size()) + " times; give it once";
    }
    if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
        const size_t colon = what.find(": ");
        if (colon != std::string::npos) {
            std::istringstream words(what.substr(colon + 2));
            std::vector<std::string> extras;
            for (std::string w; words >> w;) extras.insert(extras.begin(), w);  // back in command-line order
            std::string list;
            for (const std::string& w : extras) list += (list.empty() ? "" : " ") + w;
            return "unexpected argument" + std::string(extras.size() > 1 ? "s" : "") + " (an unknown option, or a " +
                   "value too many): " + list;
        }
    }
    return what;
}

}  // namespace lw::cli
