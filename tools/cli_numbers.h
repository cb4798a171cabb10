// tools/cli_numbers.h — number checks for the command-line tools' CLI11 options.
//
// CLI11's PositiveNumber, NonNegativeNumber and Range compare with < and >, which NaN passes
// ("--orbit nan" drew blank frames), and word their failure as a range of 0.000000 to
// 1.797693e+308. These refuse NaN and infinities and say what the option wants. Shared by
// `linework` and `linework-bench`; the engine never sees a flag (DESIGN.md).
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

#include "core/text.h"

namespace lw::cli {

namespace detail {

// A check that the option's text is a finite number x with ok(x); `what` is the message.
template <typename Ok>
CLI::Validator number_check(Ok ok, const std::string& what) {
    return CLI::Validator(
        [ok, what](std::string& text) -> std::string {
            char* end = nullptr;
            const double x = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !std::isfinite(x) || !ok(x))
                return what + ", got \"" + text + "\"";
            return {};
        },
        "NUMBER");
}

}  // namespace detail

// x > 0, finite.
inline CLI::Validator positive(const std::string& unit = "") {
    return detail::number_check([](double x) { return x > 0.0; },
                                unit.empty() ? "must be a positive number" : "must be a positive number of " + unit);
}
// x >= 0, finite.
inline CLI::Validator non_negative(const std::string& unit = "") {
    return detail::number_check([](double x) { return x >= 0.0; },
                                unit.empty() ? "must be 0 or more" : "must be a number of " + unit + ", 0 or more");
}
// lo <= x <= hi.
inline CLI::Validator within(double lo, double hi, const std::string& unit = "") {
    return detail::number_check([lo, hi](double x) { return x >= lo && x <= hi; },
                                "must be between " + lw::number_text(lo) + " and " + lw::number_text(hi) +
                                    (unit.empty() ? "" : " " + unit));
}

// A seed: a whole number from 0 to `max`, as digits (CLI11 reads "-1" into an unsigned seed
// as 2^64 - 1 without a word, and 99999999999999999999 as 0).
inline CLI::Validator seed(uint64_t max = UINT64_MAX) {
    return CLI::Validator(
        [max](std::string& text) -> std::string {
            uint64_t value = 0;
            const char* end = text.data() + text.size();
            const auto [at, problem] = std::from_chars(text.data(), end, value);
            // from_chars into an unsigned type takes digits only: no sign, and nothing for "".
            if (problem != std::errc() || at != end || value > max)
                return "must be a whole number from 0 to " + std::to_string(max) + ", got \"" + text + "\"";
            return {};
        },
        "SEED");
}

}  // namespace lw::cli
