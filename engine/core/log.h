// engine/core/log.h — minimal leveled logging to stderr.
//
// Results the user asked for (where an image went, timings) go to stdout from the tools;
// diagnostics go here so that stdout stays machine-readable.
#pragma once

#include <cstdio>
#include <string>

namespace lw {

enum class LogLevel { Quiet = 0, Info = 1, Debug = 2 };

LogLevel log_level();
void set_log_level(LogLevel level);

void log_info(const std::string& message);
void log_debug(const std::string& message);
void log_warning(const std::string& message);

}  // namespace lw
