// engine/core/error.h — the project's error type.
//
// Every failure that reaches the user is an `Error`: one line that names the file (or the
// Vulkan call, or the command-line option) and the problem. `exit_code` follows the CLI
// contract: 1 for bad input or a failed run, 2 for bad command-line usage.
#pragma once

#include <stdexcept>
#include <string>

namespace lw {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message, int exit_code = 1)
        : std::runtime_error(message), exit_code_(exit_code) {}
    int exit_code() const { return exit_code_; }

private:
    int exit_code_;
};

// A usage error (bad flag value, missing argument): exit code 2.
inline Error usage_error(const std::string& message) { return Error(message, 2); }

}  // namespace lw
