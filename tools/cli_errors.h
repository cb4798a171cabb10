// tools/cli_errors.h — CLI11's parse errors as the tools' other messages word them.
//
// CLI11 says "--frames: At Most 1 required but received 2" for a flag given twice, and can
// list arguments it did not expect in reverse order ("320x240 --sizee"). A value that is not
// a number it words as "Could not convert: --fov = abc", "--samples: abc" (a value of a set)
// or "--subdivide: Value abc not in range 0 to 6"; these say what was expected instead. The
// rest of its messages are clear as they are. Shared by `linework` and `linework-bench`.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace lw::cli {

// The option named `name` in `app` or one of its subcommands.
inline const CLI::Option* find_option(const CLI::App& app, const std::string& name) {
    for (const CLI::Option* option : app.get_options())
        if (option->get_name() == name || option->check_name(name)) return option;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if (const CLI::Option* option = find_option(*sub, name)) return option;
    return nullptr;
}

// "NAME: expected …, got "VALUE"" for a value CLI11 could not convert or match; "" when
// `what` is none of those.
inline std::string value_error_text(const std::string& what, const CLI::App& app) {
    std::string name, value;
    if (const std::string tag = "Could not convert: "; what.starts_with(tag)) {
        const size_t equals = what.find(" = ", tag.size());
        if (equals == std::string::npos) return "";
        name = what.substr(tag.size(), equals - tag.size());
        value = what.substr(equals + 3);
    } else if (const size_t colon = what.find(": "); colon != std::string::npos) {
        name = what.substr(0, colon);
        value = what.substr(colon + 2);
        if (const size_t range = value.find(" not in range "); value.starts_with("Value ") && range != std::string::npos)
            return name + ": expected a number from " + value.substr(range + 14) + ", got \"" + value.substr(6, range - 6) +
                   "\"";
        if (const size_t set = value.find(" not in {"); set != std::string::npos && value.back() == '}')
            return name + ": expected one of " + value.substr(set + 8) + ", got \"" + value.substr(0, set) + "\"";
        if (value.find(' ') != std::string::npos) return "";  // a sentence of a validator's own
    } else {
        return "";
    }
    const CLI::Option* option = find_option(app, name);
    if (!option) return "";
    // The type as --help shows it: "FLOAT", "INT", "INT:{1,4,8}", "TEXT:{flat,toon}".
    const std::string type = option->get_type_name();
    const size_t brace = type.find('{');
    const std::string expected = brace != std::string::npos ? "one of " + type.substr(brace)
                                 : type.starts_with("INT")  ? "a whole number"
                                 : type.starts_with("FLOAT") ? "a number"
                                                             : "";
    if (expected.empty()) return "";
    return name + ": expected " + expected + ", got \"" + value + "\"";
}

// `app`: the parsed (or failed) application; argv: the command line it was given.
inline std::string parse_error_text(const CLI::ParseError& e, const CLI::App& app, int argc, const char* const* argv) {
    const std::string what = e.what();
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
        const std::string tag = ": At Most 1 required but received ";
        const size_t at = what.find(tag);
        if (at != std::string::npos)
            return what.substr(0, at) + ": given " + what.substr(at + tag.size()) + " times; give it once";
    }
    if (dynamic_cast<const CLI::ConversionError*>(&e) || dynamic_cast<const CLI::ValidationError*>(&e)) {
        if (const std::string reworded = value_error_text(what, app); !reworded.empty()) return reworded;
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
