// engine/vector/stroke_io.h — stroke files in and out (formats in vector/stroke.h).
//
// Reading: .svg by extension, anything else as JSON. Every stroke needs at least one point,
// finite coordinates within ±1e6, positive finite widths and colours in [0, 1]; unknown JSON
// keys, unsupported SVG elements (text, image, …) and unknown colour names are errors. SVG
// goes through a real XML parser (vector/svg_reader.cpp): nested groups with inherited
// stroke and style, transforms, <use>, the basic shapes as strokes, CSS units; elements with
// display none or visibility hidden are not drawn. Errors are `lw::Error`s (exit code 1) whose one-line message starts
// with the file name (or `where`).
//
// Writing SVG: one <polyline> per open stroke and one <path d="M … Z"> per closed stroke, with
// its stroke colour and stroke-width (the mean width); strokes whose width varies also carry
// `data-widths="w0 w1 …"`, which the reader prefers, so that a round trip keeps every width.
// The viewBox is the set's extent when stated, else the bounds plus the widest stroke.
#pragma once

#include <filesystem>
#include <string>

#include "vector/stroke.h"

namespace lw {

[[nodiscard]] StrokeSet load_strokes(const std::filesystem::path& path);
[[nodiscard]] StrokeSet parse_strokes_json(const std::string& text, const std::string& where);
[[nodiscard]] StrokeSet parse_strokes_svg(const std::string& text, const std::string& where);  // svg_reader.cpp

// Throws lw::Error("<where>: <what>: …") unless the stroke is one a reader may return (the
// rules above); both readers call it on every stroke.
void check_stroke(const Stroke& s, const std::string& where, const std::string& what);

[[nodiscard]] std::string strokes_to_svg(const StrokeSet& set);
[[nodiscard]] std::string strokes_to_json(const StrokeSet& set);
// True for the extensions save_strokes writes: .svg and .json (any case).
[[nodiscard]] bool is_stroke_file_path(const std::filesystem::path& path);
// By extension: .json writes JSON, .svg SVG. Throws lw::Error naming the file for any other
// extension (an SVG written into x.png is no use to anyone) and when it cannot write.
void save_strokes(const std::filesystem::path& path, const StrokeSet& set);


}  // namespace lw
