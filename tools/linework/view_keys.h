// tools/linework/view_keys.h — the viewer's key names (script `key NAME` and the README).
#pragma once

#include <string>

namespace lw::cli {

// GLFW key code of a name ("s", "space", "f1", "left", …), or -1.
[[nodiscard]] int key_from_name(const std::string& name);
// "a, b, c, …": every accepted name, for messages.
[[nodiscard]] std::string key_names();

}  // namespace lw::cli
