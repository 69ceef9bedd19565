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
  // Never destroyed, so that the exit handler that removes the folder can still name it.
  static const std::filesystem::path &folder = *[] {
    std::string pattern = (std::filesystem::temp_directory_path() / "fsi-fuzz-case-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      std::abort();
    auto *made = new std::filesystem::path(pattern);
    static const std::filesystem::path *to_remove = made;
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(*to_remove, ignored);
    });
    return made;
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
