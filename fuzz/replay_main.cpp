// Replays fuzz inputs without libFuzzer: `TARGET_replay FILE_OR_DIR…` runs LLVMFuzzerTestOneInput on
// every file (directories: every regular file in them, sorted). Built by the default build so that the
// committed corpora — seeds and every past finding — are regression tests in CTest (a broken promise
// aborts, which CTest reports as a failure).
//
// With the memory limits of the libFuzzer runs (build.sh fuzz: -rss_limit_mb=2048 -malloc_limit_mb=1024):
// the address space is limited to 2 GiB (RLIMIT_AS, at least as strict as the RSS limit), and a single
// allocation of more than 1 GiB, by operator new or by GMP, is a finding (it aborts, as libFuzzer reports it).
#include <gmp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

constexpr std::size_t kMallocLimit = std::size_t(1) << 30;  // -malloc_limit_mb=1024

void* checked_malloc(std::size_t n) {
  if (n > kMallocLimit) {
    std::fprintf(stderr, "malloc limit: one allocation of %zu bytes, more than 1 GiB (-malloc_limit_mb=1024)\n", n);
    std::abort();
  }
  return std::malloc(n ? n : 1);
}
void* gmp_allocate(std::size_t n) {
  void* p = checked_malloc(n);
  if (!p) throw std::bad_alloc();
  return p;
}
void* gmp_reallocate(void* p, std::size_t, std::size_t n) {
  if (n > kMallocLimit) checked_malloc(n);  // aborts
  void* q = std::realloc(p, n);
  if (!q) throw std::bad_alloc();
  return q;
}
void gmp_free(void* p, std::size_t) { std::free(p); }

}  // namespace

void* operator new(std::size_t n) {
  if (void* p = checked_malloc(n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

int main(int argc, char** argv) {
  rlimit as;
  as.rlim_cur = as.rlim_max = rlim_t(2048) << 20;  // -rss_limit_mb=2048
  setrlimit(RLIMIT_AS, &as);
  mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const fs::path p = argv[i];
    if (fs::is_directory(p)) {
      for (const auto& e : fs::directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
  }
  std::cout << "replayed " << files.size() << " inputs\n";
  return files.empty() ? 1 : 0;
}
