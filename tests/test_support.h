// tests/test_support.h — shared helpers of the GoogleTest suite.
//
// GPU tests run on lavapipe (`--device cpu`) with the Khronos validation layer on; the
// `GpuTest` fixture fails a test that produced any WARNING or ERROR message.
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "gpu/context.h"

namespace lw::test {

inline std::filesystem::path source_dir() { return LW_SOURCE_DIR; }
inline std::filesystem::path data_dir() { return source_dir() / "tests" / "data"; }

// A fresh, empty folder under the system temp dir, named after the running test.
inline std::filesystem::path temp_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (auto& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    const auto dir = std::filesystem::temp_directory_path() / "linework-tests" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override { ctx_ = std::make_unique<Context>(ContextDesc{.device = {DeviceChoice::Kind::Cpu}, .validation = true}); }
    void TearDown() override {
        const auto messages = ctx_->validation_messages();
        EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), first: " << messages.front();
        ctx_.reset();
    }
    Context& ctx() { return *ctx_; }

private:
    std::unique_ptr<Context> ctx_;
};

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// Runs a shell command line, stdout and stderr together.
inline CommandResult run_command(const std::string& command) {
    CommandResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    size_t n = 0;
    while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// Runs the `linework` binary built beside the tests with `args` (shell-quoted by the caller),
// validation on.
inline CommandResult run_linework(const std::string& args) {
    return run_command("LINEWORK_VALIDATION=1 '" + std::string(LW_LINEWORK_EXE) + "' " + args + " 2>&1");
}

// frame_0007.png: the name `linework render` gives frame 7 of a sequence.
inline std::string frame_png(int f) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04d.png", f);
    return name;
}

// Shell-quoted path (built with +=: GCC 12 warns falsely, -Wrestrict, about "'" + std::string&&).
inline std::string quote(const std::filesystem::path& p) {
    std::string q = "'";
    q += p.string();
    q += "'";
    return q;
}

}  // namespace lw::test
