/// @file memory_reuse.h
/// @brief Keeping the memory one frame frees for the next (BENCHMARKS.md, "Memory kept for the next frame").
#pragma once

#include <cstddef>

namespace sgtllc {

/// Asks the C library to keep up to @p keep_bytes of freed memory for reuse instead of handing it back to the
/// system after every frame. Each frame allocates and frees buffers of a scan's size (a few MB); by default glibc
/// returns them, and the next frame's first touch of every page is a page fault: half of the geometric labeller's
/// time on a 120 k-point scan. Process-wide, so a library never does it on its own: an application calls it once
/// at start (the command-line tool and the benchmarks do; Python offers it as sgtllc.reuse_freed_memory()). Peak
/// memory is unchanged; freed memory up to @p keep_bytes stays with the process. Results do not change.
/// Returns false where the C library offers no such setting (not glibc) or refuses it (an allocator that replaces
/// glibc's, such as AddressSanitizer's).
bool reuseFreedMemory(std::size_t keep_bytes = std::size_t{32} << 20);

}  // namespace sgtllc
