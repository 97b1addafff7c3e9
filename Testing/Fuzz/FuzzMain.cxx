// main() for the fuzz targets built without libFuzzer (the ordinary build): runs the target
// once on every file named, or on every file in every folder named. ctest runs it over the seed
// corpus and the regression inputs, so each crash a fuzzer found stays tested.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv)
{
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i)
  {
    const std::filesystem::path p(argv[i]);
    if (std::filesystem::is_directory(p))
    {
      for (const auto& e : std::filesystem::directory_iterator(p))
      {
        if (e.is_regular_file())
        {
          files.push_back(e.path());
        }
      }
    }
    else
    {
      files.push_back(p);
    }
  }
  if (files.empty())
  {
    std::fprintf(stderr, "usage: %s FILE|FOLDER...\n", argv[0]);
    return 2;
  }
  for (const auto& f : files)
  {
    std::ifstream in(f, std::ios::binary);
    if (!in)
    {
      std::fprintf(stderr, "cannot read %s\n", f.c_str());
      return 1;
    }
    const std::vector<char> bytes(
      (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%zu inputs ran\n", files.size());
  return 0;
}
