// engine/core/memory.h — how the process's allocator treats freed memory.
//
// Input: nothing; call once at the start of main(), before any thread starts.
// Output: glibc's malloc keeps freed blocks of up to 32 MiB in its heaps for reuse instead of
// returning them to the kernel. Mesa lavapipe frees and reallocates megabytes of vertex and
// bin memory in every draw; with glibc's defaults each frame then touches thousands of fresh
// pages (4,400 page faults a frame for a 63k-triangle model at 1280×720), which cost more than
// a third of the viewer's frame time. The price: freed memory stays with the process (up to
// 512 MiB at the top of the main heap, and the per-thread heaps of at most 64 MiB keep theirs),
// so a long session's resident size follows its peak. Elsewhere (other C libraries, sanitizer
// builds, whose allocators replace malloc) it does nothing.
#pragma once

namespace lw {

// Returns false where the C library refused the settings (or has none).
bool keep_freed_memory();

}  // namespace lw
