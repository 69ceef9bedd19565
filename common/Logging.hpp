#pragma once
// Logging through spdlog: one logger per process, named after the process role, writing to
// the console and (once the output folder is known) to a log file.

#include <spdlog/spdlog.h>

#include <filesystem>
#include <string>

namespace fsi::common {

/// Sets the default logger: "[time] [role] [level] message" on stderr.
void setup_logging(const std::string &role, bool verbose = false);

enum class LogFile { truncate, append };

/// Adds a log file to the default logger: a new log (truncated), or continued (a restart's, or
/// an MPI rank's after the process that prepared its case).
void add_log_file(const std::filesystem::path &file, LogFile mode = LogFile::truncate);

} // namespace fsi::common
