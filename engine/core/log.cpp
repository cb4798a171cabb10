#include "core/log.h"

#include <atomic>

namespace lw {

namespace {
std::atomic<int> g_level{static_cast<int>(LogLevel::Info)};
thread_local WarningCapture* t_capture = nullptr;
}  // namespace

WarningCapture::WarningCapture() : outer_(t_capture) { t_capture = this; }
WarningCapture::~WarningCapture() { t_capture = outer_; }

LogLevel log_level() { return static_cast<LogLevel>(g_level.load()); }
void set_log_level(LogLevel level) { g_level.store(static_cast<int>(level)); }

void log_info(const std::string& message) {
    if (g_level.load() >= static_cast<int>(LogLevel::Info)) std::fprintf(stderr, "%s\n", message.c_str());
}
void log_debug(const std::string& message) {
    if (g_level.load() >= static_cast<int>(LogLevel::Debug)) std::fprintf(stderr, "debug: %s\n", message.c_str());
}
void log_warning(const std::string& message) {
    if (t_capture) {
        t_capture->messages_.push_back(message);
        return;
    }
    std::fprintf(stderr, "warning: %s\n", message.c_str());
}

}  // namespace lw
