// engine/vector/json_object.h — the top of a JSON input file (curves, strokes): one object
// whose keys are all known; every error names the file (`where`).
#pragma once

#include <algorithm>
#include <initializer_list>
#include <utility>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/text.h"

namespace lw {

// `shape` says what the object should be, for the message when it is not one
// (e.g. "a curve must be a JSON object with \"points\"").
inline nlohmann::json parse_json_object(const std::string& text, const std::string& where,
                                        std::initializer_list<std::string_view> keys, const std::string& shape) {
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {  // syntax, and numbers past double's range
        throw Error(where + ": not valid JSON (" + json_message(e.what()) + ")");
    }
    if (!root.is_object()) throw Error(where + ": " + shape);
    // The other kind of file, given where this one is wanted (a curve as --along, a stroke
    // file as --curve): said as such, not as its first key being unknown.
    const std::pair<std::string_view, const char*> kinds[] = {{"points", "a curve file ({\"points\": [...]})"},
                                                              {"strokes", "a stroke file ({\"strokes\": [...]})"}};
    for (const auto& [key, kind] : kinds)
        if (root.contains(key) && std::find(keys.begin(), keys.end(), key) == keys.end())
            throw Error(where + ": is " + kind + "; " + shape);
    for (const auto& [key, value] : root.items()) {
        bool known = false;
        for (std::string_view k : keys) known = known || key == k;
        if (!known) throw Error(where + ": " + key + ": unknown key");
    }
    return root;
}

}  // namespace lw
