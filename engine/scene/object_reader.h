// engine/scene/object_reader.h — one JSON object of a scene file, read key by key: every
// value checked for type and range, every error naming the file and the key path
// ("lines.suggestive.threshold"), unknown keys refused (scene_file.cpp, line_set_file.cpp).
#pragma once

#include <filesystem>
#include <set>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/color.h"
#include "core/error.h"
#include "core/log.h"
#include "core/text.h"

namespace lw::scene_detail {

using json = nlohmann::json;

// A path written in a scene file: relative ones are relative to the file's folder.
inline std::string resolve_against(const std::filesystem::path& file, const std::string& name) {
    const std::filesystem::path p(name);
    return (p.is_absolute() ? p : file.parent_path() / p).string();
}

// Reads one JSON object, remembering which keys were consumed so that the rest can be
// reported as unknown. `where` is the key path used in messages ("" for the root).
class ObjectReader {
public:
    ObjectReader(const json& object, std::string where, const std::filesystem::path& file)
        : object_(object), where_(std::move(where)), file_(file) {
        if (!object_.is_object()) fail(where_.empty() ? "the scene must be a JSON object" : "must be an object");
    }

    bool boolean(const std::string& key) {
        const json& v = at(key);
        if (!v.is_boolean()) fail_key(key, "expected true or false, got " + v.dump());
        return v.get<bool>();
    }

    bool has(const std::string& key) {
        known_.insert(key);
        return object_.contains(key);
    }
    const json& at(const std::string& key) { return object_.at(key); }
    std::string path(const std::string& key) const { return where_.empty() ? key : where_ + "." + key; }

    [[noreturn]] void fail_key(const std::string& key, const std::string& problem) const {
        throw Error(file_.string() + ": " + path(key) + ": " + problem);
    }
    [[noreturn]] void fail(const std::string& problem) const {
        throw Error(file_.string() + ": " + (where_.empty() ? "" : where_ + ": ") + problem);
    }
    // A key that is read but changes nothing where it is (kept for files written before it
    // did): said, not refused.
    void warn(const std::string& problem) const {
        log_warning(file_.string() + ": " + (where_.empty() ? "" : where_ + ": ") + problem);
    }

    double number(const std::string& key, double lo, double hi) {
        const json& v = at(key);
        if (!v.is_number()) fail_key(key, "expected a number, got " + std::string(v.type_name()));
        const double x = v.get<double>();
        if (!std::isfinite(x) || x < lo || x > hi)
            fail_key(key, "must be between " + number_text(lo) + " and " + number_text(hi) + ", got " + v.dump());
        return x;
    }

    std::string string_of(const std::string& key, const std::set<std::string>& allowed = {}) {
        const json& v = at(key);
        if (!v.is_string()) fail_key(key, "expected a string, got " + std::string(v.type_name()));
        std::string s = v.get<std::string>();
        if (!allowed.empty() && !allowed.count(s)) {
            std::string list;
            for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
            fail_key(key, "must be one of " + list + ", got \"" + s + "\"");
        }
        return s;
    }

    // A non-empty file name, resolved against the scene file's folder; `what` says what the
    // file should be ("a SLAM file (.exr)") when it is empty.
    std::string file_path(const std::string& key, const std::string& what) {
        const std::string name = string_of(key);
        if (name.empty()) fail_key(key, "expected " + what);
        return resolve_against(file_, name);
    }

    glm::vec3 vec3(const std::string& key, double lo = -1e30, double hi = 1e30) {
        const json& v = at(key);
        if (!v.is_array() || v.size() != 3) fail_key(key, "expected an array of 3 numbers");
        glm::vec3 out;
        for (int i = 0; i < 3; ++i) {
            if (!v[i].is_number()) fail_key(key, "expected an array of 3 numbers");
            const double x = v[i].get<double>();
            if (!std::isfinite(x) || x < lo || x > hi)
                fail_key(key, "components must be between " + number_text(lo) + " and " + number_text(hi));
            out[i] = static_cast<float>(x);
        }
        return out;
    }

    // A colour: [r, g, b] in [0, 1] or a string as stroke files and SVG write it ("#rrggbb",
    // "#rgb", "rgb(…)", a colour name; core/color.h).
    glm::vec3 color(const std::string& key) {
        const json& v = at(key);
        if (v.is_string()) return parse_color(v.get<std::string>(), file_.string() + ": " + path(key));
        if (!v.is_array()) fail_key(key, "expected [r, g, b] in [0, 1] or a colour string such as \"#rrggbb\"");
        return vec3(key, 0.0, 1.0);
    }

    // Every key of the object must have been asked for.
    void reject_unknown() const {
        for (const auto& [key, value] : object_.items())
            if (!known_.count(key)) {
                std::string list;
                for (const auto& k : known_) list += (list.empty() ? "" : ", ") + k;
                fail_key(key, "unknown key (known here: " + list + ")");
            }
    }


private:

    const json& object_;
    std::string where_;
    const std::filesystem::path& file_;
    std::set<std::string> known_;
};

}  // namespace lw::scene_detail
