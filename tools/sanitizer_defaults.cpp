// tools/sanitizer_defaults.cpp — linked only into sanitizer builds (LINEWORK_SANITIZE=ON).
//
// Mesa's lavapipe leaks a few small allocations; LeakSanitizer reports them after the
// Vulkan loader has unloaded the driver, with no stack frames left to suppress. Address and
// undefined-behaviour checks stay on; leak checks are off unless ASAN_OPTIONS says otherwise.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
