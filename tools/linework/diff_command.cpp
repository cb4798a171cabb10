// `linework diff A.png B.png` — the golden-image comparison the tests use.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "commands.h"
#include "cli_numbers.h"
#include "core/image.h"
#include "io/image_io.h"

namespace lw::cli {

namespace {

struct DiffOptions {
    std::string a, b, out;
    int max_error = 255;
    double min_psnr = 40.0;
    int tolerance = 16;
    double max_differing = 0.005;
};

int run_diff(const DiffOptions& o) {
    std::error_code ec;
    for (const std::string& input : {o.a, o.b})
        if (!o.out.empty() && std::filesystem::equivalent(o.out, input, ec))
            throw usage_error("--out " + o.out + ": is the image " + input + " being compared; give another name");
    const ImageRGBA8 a = read_image_rgba8(o.a);
    const ImageRGBA8 b = read_image_rgba8(o.b);
    if (a.width != b.width || a.height != b.height)
        throw Error(o.a + " (" + std::to_string(a.width) + "x" + std::to_string(a.height) + ") and " + o.b + " (" +
                    std::to_string(b.width) + "x" + std::to_string(b.height) + ") differ in size");
    const ImageDiff d = compare_images(a, b, o.tolerance);
    std::printf("max abs error: %d\n", d.max_abs_error);
    std::printf("rmse: %.4f\n", d.rmse);
    if (std::isinf(d.psnr_db))
        std::printf("psnr: inf dB\n");
    else
        std::printf("psnr: %.2f dB\n", d.psnr_db);
    std::printf("differing pixels (> %d): %.4f %%\n", o.tolerance, 100.0 * d.differing_fraction);
    if (!o.out.empty()) {
        write_png(o.out, d.diff);
        std::printf("wrote %s\n", o.out.c_str());
    }
    // Which thresholds were passed, so that a MISMATCH says why.
    std::string failed;
    char part[160];
    if (d.max_abs_error > o.max_error) {
        std::snprintf(part, sizeof part, "; max abs error %d > --max-error %d", d.max_abs_error, o.max_error);
        failed += part;
    }
    if (d.psnr_db < o.min_psnr) {
        std::snprintf(part, sizeof part, "; psnr %.2f dB < --min-psnr %g", d.psnr_db, o.min_psnr);
        failed += part;
    }
    if (d.differing_fraction > o.max_differing) {
        std::snprintf(part, sizeof part, "; differing pixels %.4f %% > --max-differing %g (%g %%)",
                      100.0 * d.differing_fraction, o.max_differing, 100.0 * o.max_differing);
        failed += part;
    }
    std::printf("%s\n", failed.empty() ? "match" : ("MISMATCH: " + failed.substr(2)).c_str());
    return failed.empty() ? 0 : 1;
}

}  // namespace

Runner add_diff_command(CLI::App& app) {
    auto o = std::make_shared<DiffOptions>();
    CLI::App* cmd = app.add_subcommand(
        "diff",
        "Compare two images: prints max absolute error, RMSE, PSNR and the share of differing pixels;\n"
        "exits 1 when any threshold is passed.");
    cmd->add_option("a", o->a, "First image")->required();
    cmd->add_option("b", o->b, "Second image")->required();
    cmd->add_option("--out", o->out, "Write the amplified difference (|A-B| x 8) as PNG")->check(output_file(".png"));
    cmd->add_option("--max-error", o->max_error, "Largest per-channel difference allowed (0-255)")
        ->check(CLI::Range(0, 255))
        ->capture_default_str();
    cmd->add_option("--min-psnr", o->min_psnr, "Smallest PSNR allowed, dB")
        ->check(within(0.0, 1000.0, "dB"))
        ->capture_default_str();
    cmd->add_option("--tolerance", o->tolerance, "Per-channel difference under which a pixel still matches")
        ->check(CLI::Range(0, 255))
        ->capture_default_str();
    cmd->add_option("--max-differing", o->max_differing,
                    "Largest share of differing pixels allowed, a fraction 0-1 (0.005 is the 0.5 % printed)")
        ->check(within(0.0, 1.0))
        ->capture_default_str();
    return [o] { return run_diff(*o); };
}

}  // namespace lw::cli
