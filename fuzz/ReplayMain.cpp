// Replays files through a fuzz target without libFuzzer: the test suite runs every seed and every
// input that once crashed (fuzz/corpus, fuzz/regressions) through the loaders, built as they ship.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);
extern "C" __attribute__((weak)) int LLVMFuzzerInitialize(int *argc, char ***argv);

int main(int argc, char **argv)
{
  if (LLVMFuzzerInitialize)
    LLVMFuzzerInitialize(&argc, &argv);
  std::size_t n = 0;
  for (int a = 1; a < argc; ++a) {
    std::error_code ec;
    if (!std::filesystem::is_directory(argv[a], ec))
      continue; // a target with no regressions yet
    for (const auto &e : std::filesystem::directory_iterator(argv[a])) {
      if (!e.is_regular_file())
        continue;
      std::ifstream f(e.path(), std::ios::binary);
      const std::vector<char> bytes{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t *>(bytes.data()), bytes.size());
      ++n;
    }
  }
  std::printf("%zu inputs replayed, none crashed\n", n);
  std::error_code ec; // the targets' scratch folder (FuzzFile.h), if one was made
  std::filesystem::remove_all(std::filesystem::temp_directory_path() / ("pm-fuzz-" + std::to_string(::getpid())), ec);
  return n > 0 ? 0 : 1;
}
