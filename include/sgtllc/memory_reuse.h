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

/// Backs the next @p bytes of the heap with huge pages where the kernel offers them (transparent huge pages in
/// `madvise` or `always` mode): one page fault per 2 MB instead of one per 4 KB, which on a virtual machine is most
/// of a short command's time (BENCHMARKS.md, "Huge pages for the heap"). It makes the heap grow by at least
/// @p bytes at a time (glibc's top pad), grows it once and marks that region MADV_HUGEPAGE; the heap beyond it keeps
/// normal pages. Process-wide, so a library never does it on its own: call it once at start, after
/// reuseFreedMemory (whose mmap threshold keeps the blocks of a scan's size on the heap; the command-line tool does,
/// Python offers sgtllc.huge_page_heap()). Memory in use grows by at most one huge page per touched 2 MB; results
/// do not change. Returns false, glibc's top pad back at its default, where the C library or the kernel offers no
/// such setting (not glibc, an allocator that replaces glibc's, a kernel built without transparent huge pages) or
/// the heap did not grow; true means the region is marked, which a kernel in `never` mode then ignores.
bool hugePageHeap(std::size_t bytes = std::size_t{64} << 20);

}  // namespace sgtllc
