// `linework devices` — the Vulkan devices `--device N` can name.
#include <cstdio>

#include "commands.h"
#include "gpu/context.h"

namespace lw::cli {

Runner add_devices_command(CLI::App& app) {
    app.add_subcommand("devices", "List the Vulkan devices and which one --device auto picks.");
    return [] {
        const auto devices = list_devices();
        if (devices.empty()) {
            std::printf("no Vulkan devices (install mesa-vulkan-drivers for lavapipe)\n");
            return 1;
        }
        const int chosen = auto_device_index(devices);
        for (const auto& d : devices)
            std::printf("[%d] %s%s%s\n", d.index, d.describe().c_str(),
                        d.suitable ? "" : (" — unsuitable: " + d.unsuitable_reason).c_str(),
                        d.index == chosen ? "  <- --device auto" : "");
        if (chosen < 0) {
            std::printf("--device auto: no suitable device\n");
            return 1;
        }
        std::printf("--device auto takes [%d] %s\n", chosen, devices[size_t(chosen)].name.c_str());
        return 0;
    };
}

}  // namespace lw::cli
