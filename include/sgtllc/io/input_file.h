/// @file input_file.h
/// @brief How every sgtllc reader opens and sizes a file: the messages it throws, and the most one file may cost in
///        memory, so that a reader refuses an input too large for the machine by name instead of failing to
///        allocate.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

namespace sgtllc::io {

using FilePtr = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

/// Opens a file for binary reading. Throws sgtllc::Error `cannot open PATH: REASON` (strerror, or "is a
/// directory").
FilePtr openForReading(const std::string& path);

/// The whole contents of a file (opened as openForReading); throws `cannot read PATH: REASON` on a read error, and
/// `cannot read PATH: N bytes, more than this machine can load (M GiB of memory)` for a file larger than
/// loadableBytes() (a sparse file of a terabyte), before allocating anything.
std::string readWholeFile(const std::string& path);

/// The most one file may cost in memory: this machine's physical memory, or the address-space limit when one is set
/// (ulimit -v).
uint64_t loadableBytes();

/// "1.5 GiB": @p bytes in GiB with one decimal, for messages.
std::string gibText(uint64_t bytes);

}  // namespace sgtllc::io
