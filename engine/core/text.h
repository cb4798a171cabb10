// core/text.h — the string helpers every reader of hand-written files needs.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

namespace lw {

// Without leading and trailing white space.
inline std::string trim(const std::string& s) {
    size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

// ASCII lower case (file extensions, SVG tag and colour names).
inline std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// " '.obj'", or " (no extension)": how an error names a file extension (lower case).
inline std::string extension_phrase(const std::string& extension) {
    return extension.empty() ? std::string(" (no extension)") : " '" + extension + "'";
}

// A number as messages write it: whole numbers without a point (1000, not 1e+03), others in
// %g (0.1, not 0.100000).
inline std::string number_text(double v) {
    char text[48];
    if (std::isfinite(v) && v == std::round(v) && std::abs(v) < 1e15) std::snprintf(text, sizeof text, "%.0f", v);
    else std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// A library's message made one line of an error: trailing newlines dropped, inner ones as
// "; ", and cut at `max_length` (tinygltf can quote a whole data URI).
inline std::string one_line(std::string text, size_t max_length = 400) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    std::string out;
    for (char c : text) {
        if (c == '\n') {
            out += "; ";
        } else if (c != '\r') {
            out += c;
        }
    }
    if (out.size() > max_length) out = out.substr(0, max_length) + "...";
    return out;
}

// nlohmann::json's exception text without its "[json.exception.out_of_range.403] " tag, which
// names the library's error class and means nothing to a user: "key 'frame' not found".
inline std::string json_message(const std::string& what) {
    if (what.rfind("[json.exception.", 0) != 0) return what;
    const size_t end = what.find("] ");
    return end == std::string::npos ? what : what.substr(end + 2);
}

}  // namespace lw
