// Engine core on lavapipe: device choice, buffers, compute pipelines, timestamps.
#include <cmath>
#include <numeric>
#include <vector>

#include "core/error.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "gpu/timestamps.h"
#include "gpu/vk_check.h"
#include "saxpy_comp.h"
#include "test_support.h"

namespace lw {
namespace {

using test::GpuTest;

TEST(DeviceChoice, ParsesKeywordsAndIndices) {
    EXPECT_EQ(parse_device_choice("auto").kind, DeviceChoice::Kind::Auto);
    EXPECT_EQ(parse_device_choice("cpu").kind, DeviceChoice::Kind::Cpu);
    EXPECT_EQ(parse_device_choice("gpu").kind, DeviceChoice::Kind::Gpu);
    const DeviceChoice n = parse_device_choice("2");
    EXPECT_EQ(n.kind, DeviceChoice::Kind::Index);
    EXPECT_EQ(n.index, 2);
    for (const char* bad : {"", "GPU ", "-1", "1.5", "fast"}) {
        try {
            (void)parse_device_choice(bad);
            ADD_FAILURE() << "accepted \"" << bad << "\"";
        } catch (const ParameterError& e) {
            // The engine names its parameter; `linework` re-throws it as --device (ErrorTable).
            EXPECT_EQ(e.exit_code(), 2) << bad;
            EXPECT_EQ(e.name(), "device");
            EXPECT_EQ(std::string(e.what()).rfind("device: expected auto, cpu, gpu", 0), 0u) << e.what();
        }
    }
}

TEST(DeviceChoice, CpuPicksLavapipe) {
    Context ctx({.device = {DeviceChoice::Kind::Cpu}});
    EXPECT_EQ(ctx.info().type, VK_PHYSICAL_DEVICE_TYPE_CPU);
    EXPECT_GE(ctx.info().api_version, VK_API_VERSION_1_3);
}

TEST(DeviceChoice, GpuWithoutGpuFailsClearly) {
    const auto devices = list_devices();
    const bool has_gpu = std::any_of(devices.begin(), devices.end(), [](const DeviceInfo& d) {
        return d.suitable && d.type != VK_PHYSICAL_DEVICE_TYPE_CPU && d.type != VK_PHYSICAL_DEVICE_TYPE_OTHER;
    });
    if (has_gpu) GTEST_SKIP() << "this machine has a GPU";
    try {
        Context ctx({.device = {DeviceChoice::Kind::Gpu}});
        ADD_FAILURE() << "created a context on " << ctx.info().name;
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("no GPU"), std::string::npos) << message;
        EXPECT_NE(message.find("llvmpipe"), std::string::npos) << "the message should list the devices: " << message;
    }
}

TEST(DeviceChoice, IndexOutOfRangeFails) {
    EXPECT_THROW(Context({.device = {DeviceChoice::Kind::Index, 99}}), Error);
}

TEST_F(GpuTest, BufferRoundTrip) {
    std::vector<uint32_t> data(100000);
    std::iota(data.begin(), data.end(), 7u);
    Buffer buffer = upload_buffer(ctx(), data, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  "round trip");
    EXPECT_EQ(read_buffer_as<uint32_t>(ctx(), buffer), data);
}

TEST_F(GpuTest, ComputeMatchesCpu) {
    const uint32_t n = 1000;  // not a multiple of the workgroup size: tests the bounds check
    std::vector<float> x(n), y(n);
    for (uint32_t i = 0; i < n; ++i) {
        x[i] = std::sin(float(i));
        y[i] = float(i) * 0.25f;
    }
    const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    Buffer bx = upload_buffer(ctx(), x, usage, "x");
    Buffer by = upload_buffer(ctx(), y, usage, "y");
    ComputePipeline saxpy(ctx(), {.spirv = LW_SPIRV(saxpy_comp_spv), .storage_buffers = 2,
                                  .push_constant_size = 8, .name = "saxpy"});
    struct {
        float a;
        uint32_t n;
    } push{2.5f, n};
    ctx().submit_and_wait([&](VkCommandBuffer cmd) { saxpy.dispatch(ctx(), cmd, {&bx, &by}, &push, (n + 63) / 64); });
    const auto result = read_buffer_as<float>(ctx(), by);
    ASSERT_EQ(result.size(), n);
    for (uint32_t i = 0; i < n; ++i) EXPECT_FLOAT_EQ(result[i], 2.5f * x[i] + y[i]) << i;
}

TEST_F(GpuTest, TimestampsMeasureWork) {
    ASSERT_TRUE(ctx().has_timestamps());
    GpuTimer timer(ctx());
    const uint32_t n = 1 << 20;
    std::vector<float> data(n, 1.0f);
    const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    Buffer bx = upload_buffer(ctx(), data, usage, "x");
    Buffer by = upload_buffer(ctx(), data, usage, "y");
    ComputePipeline saxpy(ctx(), {.spirv = LW_SPIRV(saxpy_comp_spv), .storage_buffers = 2,
                                  .push_constant_size = 8, .name = "saxpy"});
    struct {
        float a;
        uint32_t n;
    } push{1.0f, n};
    ctx().submit_and_wait([&](VkCommandBuffer cmd) {
        timer.reset(cmd);
        timer.begin(cmd, "saxpy");
        saxpy.dispatch(ctx(), cmd, {&bx, &by}, &push, n / 64);
        timer.end(cmd);
    });
    const auto times = timer.results();
    ASSERT_EQ(times.size(), 1u);
    EXPECT_EQ(times[0].name, "saxpy");
    EXPECT_GT(times[0].ms, 0.0);
    EXPECT_LT(times[0].ms, 10000.0);
}

TEST_F(GpuTest, DispatchRejectsWrongBufferCount) {
    ComputePipeline saxpy(ctx(), {.spirv = LW_SPIRV(saxpy_comp_spv), .storage_buffers = 2,
                                  .push_constant_size = 8, .name = "saxpy"});
    std::vector<float> data(64, 0.0f);
    Buffer bx = upload_buffer(ctx(), data, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "x");
    float push[2] = {};
    EXPECT_THROW(ctx().submit_and_wait([&](VkCommandBuffer cmd) { saxpy.dispatch(ctx(), cmd, {&bx}, push, 1); }),
                 Error);
}

VkResult failing_vulkan_call(int) { return VK_ERROR_OUT_OF_DEVICE_MEMORY; }

TEST(VkCheck, NamesTheCallAndResult) {
    try {
        LW_VK(failing_vulkan_call(3));
        ADD_FAILURE();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "failing_vulkan_call failed: VK_ERROR_OUT_OF_DEVICE_MEMORY");
    }
    EXPECT_NO_THROW(LW_VK(VK_SUCCESS));
}

}  // namespace
}  // namespace lw
