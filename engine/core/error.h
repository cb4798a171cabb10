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

// A bad value of an engine parameter, named as the engine knows it ("device", "ribbon piece"):
// what() is NAME + rest, rest being ": problem" or " VALUE: problem". The engine does not know
// whether the value came from a flag, a scene key or a Python argument; the caller that does
// re-throws it under that name (tools/linework/commands.h, flags_named).
class ParameterError : public Error {
public:
    ParameterError(std::string name, std::string rest, int exit_code = 2)
        : Error(joined(name, rest), exit_code), name_(std::move(name)), rest_(std::move(rest)) {}
    const std::string& name() const { return name_; }
    const std::string& rest() const { return rest_; }

private:
    // Appended rather than `a + b`, which GCC 12 warns about (-Wrestrict, a false positive).
    static std::string joined(const std::string& a, const std::string& b) {
        std::string s;
        s.reserve(a.size() + b.size());
        return s.append(a).append(b);
    }
    std::string name_, rest_;
};

}  // namespace lw
