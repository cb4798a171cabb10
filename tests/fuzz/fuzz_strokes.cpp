// Stroke and curve files, JSON and the SVG subset; the first byte picks the reader.
#include <string>

#include "core/error.h"
#include "fuzz_support.h"
#include "vector/curve.h"
#include "vector/stroke_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
        switch (data[0] % 4) {
            case 0: (void)lw::parse_strokes_json(text, "fuzz.json"); break;
            case 1: (void)lw::parse_strokes_svg(text, "fuzz.svg"); break;
            case 2: (void)lw::parse_curve_json(text, "fuzz.json"); break;
            default: (void)lw::parse_curve_svg(text, "fuzz.svg"); break;
        }
    } catch (const lw::Error&) {
    }
    return 0;
}
