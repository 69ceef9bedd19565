// A main for the fuzz targets in builds without libFuzzer (g++): runs every file given, or every
// file in every folder given, through LLVMFuzzerTestOneInput once: the committed corpus and
// past crashers replayed as a regression test (F1 of docs/security.md).

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);

namespace {
void run_file(const std::filesystem::path &file) {
  std::ifstream in(file, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t *>(bytes.data()), bytes.size());
}
} // namespace

int main(int argc, char **argv) {
  long inputs = 0;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path path(argv[i]);
    if (std::filesystem::is_directory(path)) {
      for (const auto &entry : std::filesystem::recursive_directory_iterator(path))
        if (entry.is_regular_file()) {
          run_file(entry.path());
          ++inputs;
        }
    } else if (std::filesystem::is_regular_file(path)) {
      run_file(path);
      ++inputs;
    } else if (path.parent_path().filename() != "crashers") { // no crasher of this target yet: fine
      std::fprintf(stderr, "no such file or folder: %s\n", argv[i]);
      return 2;
    }
  }
  std::printf("%ld inputs replayed without a crash\n", inputs);
  return inputs > 0 ? 0 : 1;
}
