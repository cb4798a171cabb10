// engine/core/log.h — minimal leveled logging to stderr.
//
// Results the user asked for (where an image went, timings) go to stdout from the tools;
// diagnostics go here so that stdout stays machine-readable.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace lw {

enum class LogLevel { Quiet = 0, Info = 1, Debug = 2 };

LogLevel log_level();
void set_log_level(LogLevel level);

void log_info(const std::string& message);
void log_debug(const std::string& message);
void log_warning(const std::string& message);

// While a capture lives, warnings said on its thread are kept in it instead of written to
// stderr (captures nest; the innermost takes them). The Python module turns them into Python
// warnings, which scripts can filter or catch, once its call is done.
class WarningCapture {
public:
    WarningCapture();
    ~WarningCapture();
    WarningCapture(const WarningCapture&) = delete;
    WarningCapture& operator=(const WarningCapture&) = delete;
    [[nodiscard]] const std::vector<std::string>& messages() const { return messages_; }

private:
    friend void log_warning(const std::string& message);
    std::vector<std::string> messages_;
    WarningCapture* outer_;
};

}  // namespace lw
