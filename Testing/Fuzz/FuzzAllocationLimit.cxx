// The allocator of the VDB fuzz target: requests above 64 MiB fail with std::bad_alloc.
//
// OpenVDB allocates what some size fields of a file say before it reads the bytes (the length
// of a zlib or blosc block, io/Compression.cc). A corrupt size of gigabytes is, in an ordinary
// process, either refused by the allocator (std::bad_alloc, which vtkOpenVDBImageReader
// reports as an error) or reserved untouched and freed when the read runs past the end of the
// file. Under AddressSanitizer a throwing operator new that cannot be served aborts the process
// instead (LLVM 14 has no way to make it throw), and libFuzzer counts any request above
// -malloc_limit_mb as a crash. This models the ordinary allocator: the fuzz inputs are tiny
// (at most 4096 voxels are read, from files of at most a few hundred kilobytes), so no valid
// input asks for anywhere near 64 MiB.
#include <cstdlib>
#include <new>

namespace
{
constexpr std::size_t Limit = std::size_t(64) << 20;

void* Allocate(std::size_t n)
{
  if (n > Limit)
  {
    throw std::bad_alloc();
  }
  if (void* p = std::malloc(n ? n : 1))
  {
    return p;
  }
  throw std::bad_alloc();
}
} // namespace

void* operator new(std::size_t n)
{
  return Allocate(n);
}
void* operator new[](std::size_t n)
{
  return Allocate(n);
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept
{
  return n > Limit ? nullptr : std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept
{
  return n > Limit ? nullptr : std::malloc(n ? n : 1);
}
void operator delete(void* p) noexcept
{
  std::free(p);
}
void operator delete[](void* p) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept
{
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}
