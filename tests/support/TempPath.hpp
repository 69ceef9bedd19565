#pragma once
// Test support: unique paths under the system's temporary folder (a folder or a file), each
// removed with everything under it when the test program ends, so that test runs leave nothing
// in /tmp.

#include <filesystem>
#include <random>
#include <string>
#include <system_error>
#include <vector>

namespace fsi::test_support {

/// <tmp>/<prefix><random number><suffix>, not created; removed at the end of the program.
inline std::filesystem::path temp_path(const std::string &prefix, const std::string &suffix = "") {
  struct Removed {
    std::vector<std::filesystem::path> paths;
    ~Removed() {
      std::error_code ignored;
      for (const auto &p : paths)
        std::filesystem::remove_all(p, ignored);
    }
  };
  static Removed removed;
  static std::mt19937_64 rng(std::random_device{}());
  removed.paths.push_back(std::filesystem::temp_directory_path() / (prefix + std::to_string(rng()) + suffix));
  return removed.paths.back();
}

} // namespace fsi::test_support
