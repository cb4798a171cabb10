// engine/vector/xml.h — an SVG file's text as a pugixml document, or one error naming the
// file and the line (pugixml reports a byte offset; people read lines). Shared by the
// stroke reader (svg_reader.cpp) and the curve reader (curve.cpp).
#pragma once

#include <algorithm>
#include <memory>
#include <string>

#include <pugixml.hpp>

#include "core/error.h"

namespace lw {

inline std::unique_ptr<pugi::xml_document> parse_xml(const std::string& text, const std::string& where) {
    auto doc = std::make_unique<pugi::xml_document>();
    const pugi::xml_parse_result parsed = doc->load_buffer(text.data(), text.size());
    if (!parsed) {
        const size_t end = std::min(text.size(), size_t(std::max<ptrdiff_t>(parsed.offset, 0)));
        const auto line = 1 + std::count(text.begin(), text.begin() + ptrdiff_t(end), '\n');
        throw Error(where + ": XML: " + parsed.description() + " at line " + std::to_string(line));
    }
    return doc;
}

}  // namespace lw
