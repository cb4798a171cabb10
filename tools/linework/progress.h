// tools/linework/progress.h — progress of a long run on stderr: a bar on a terminal, a line
// every tenth of the work otherwise (logs stay short). Shared by `render` (frames) and
// `slam` (levels).
#pragma once

#include <cstdio>
#include <string>
#include <utility>

#include <unistd.h>

namespace lw::cli {

class Progress {
public:
    // `noun`: what is counted, singular ("frame", "level").
    Progress(int total, std::string noun) : total_(total), noun_(std::move(noun)), tty_(isatty(fileno(stderr)) != 0) {}
    // `done` items finished; the last was item `item` and took `ms`.
    void update(int done, int item, double ms) {
        if (total_ <= 1) return;
        if (tty_) {
            const int width = 30, filled = width * done / total_;
            std::fprintf(stderr, "\r[%s%s] %d/%d %s %d (%.0f ms)%s", std::string(size_t(filled), '#').c_str(),
                         std::string(size_t(width - filled), '.').c_str(), done, total_, noun_.c_str(), item, ms,
                         done == total_ ? "\n" : "");
        } else if (done == total_ || done * 10 / total_ != (done - 1) * 10 / total_) {
            std::fprintf(stderr, "progress: %d/%d %ss (%s %d, %.0f ms)\n", done, total_, noun_.c_str(), noun_.c_str(),
                         item, ms);
        }
    }

private:
    int total_;
    std::string noun_;
    bool tty_;
};

}  // namespace lw::cli
