#pragma once
// A StateArchive on disk, written so that a crash never leaves a file that looks complete but
// is not: the bytes go to "<name>.tmp", are synced, and the file is renamed over <name> (and the
// folder synced), so <name> is the old file or the new one, never a part of either.
//
// Format (little-endian, as every machine the project runs on):
//   "FSI-STATE-ARCHIVE\n"  18 bytes
//   u32 format_version (1)  u32 byte-order mark 0x01020304
//   u64 number of entries   u64 body length in bytes
//   body: per entry (in name order): u32 name length, name, u8 kind (1 doubles, 2 integer,
//         3 text), then doubles: u32 rank, u64 dims[rank], the values (f64); integer: i64;
//         text: u64 length, bytes
//   u64 FNV-1a of the body
// read_archive() refuses, naming the file: a short or long file, a wrong header, a checksum
// that does not match (a flipped bit), an entry that runs past the body.

#include "checkpoint/StateArchive.hpp"

#include <cstdint>
#include <filesystem>

namespace fsi::checkpoint {

/// Writes `archive` to `path` atomically (temporary file, fsync, rename, fsync of the folder).
/// Returns the checksum of the body (16 hex digits). Throws std::runtime_error naming the path.
std::string write_archive(const std::filesystem::path &path, const StateArchive &archive);

/// Reads and verifies an archive; throws CheckpointError naming the path and the fault.
StateArchive read_archive(const std::filesystem::path &path);

/// The checksum a file's trailer holds, after checking it against the body (as read_archive).
std::string archive_checksum(const std::filesystem::path &path);

} // namespace fsi::checkpoint
