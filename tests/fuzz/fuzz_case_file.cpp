// Fuzz target: the case parser. Each input is a case.yaml (in a temporary folder); loading it
// must give a configuration or a ConfigError (a user error naming the file, the key and what is
// allowed), never a crash, an undefined behaviour or any other exception (which would reach a
// user as an unhelpful message).

#include "case/CaseConfig.hpp"
#include "common/UserError.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  static const std::filesystem::path folder = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "fsi-fuzz-case-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      std::abort();
    return std::filesystem::path(pattern);
  }();
  {
    std::ofstream out(folder / "case.yaml", std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
  }
  try {
    const auto config = fsi::case_config::CaseConfig::load(folder);
    (void)config.fingerprint();
  } catch (const fsi::common::UserError &) {
    // refused with a message: fine
  } catch (const std::exception &e) {
    std::fprintf(stderr, "the case parser let through a %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  }
  return 0;
}
