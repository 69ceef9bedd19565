#include "Logging.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>

namespace fsi::common {

void setup_logging(const std::string &role, bool verbose) {
  auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  auto logger = std::make_shared<spdlog::logger>(role, console);
  logger->set_pattern("[%H:%M:%S.%e] [%n] [%^%l%$] %v");
  logger->set_level(verbose ? spdlog::level::debug : spdlog::level::info);
  spdlog::set_default_logger(logger);
}

void add_log_file(const std::filesystem::path &file, LogFile mode) {
  auto sink = std::make_shared<spdlog::sinks::basic_file_sink_mt>(file.string(), mode == LogFile::truncate);
  sink->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [%n] [%l] %v");
  spdlog::default_logger()->sinks().push_back(sink);
  // A log file is for following a run as it goes (tail -f) and for reading after a kill:
  // each line of level info and above is written out at once (debug lines are buffered).
  spdlog::default_logger()->flush_on(spdlog::level::info);
}

} // namespace fsi::common
