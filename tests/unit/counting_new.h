#pragma once
// Replaces the global operator new with one that counts its calls while g_counting is set, so a
// test can assert that a piece of code does not allocate through std containers (Eigen's own
// allocations are caught by EIGEN_RUNTIME_NO_MALLOC), and records the largest request in
// g_largest_new [bytes], so a test can bound what a piece of code asks for at once. Include it
// in exactly one translation unit of a test executable: the replacement functions are defined
// here.

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_news{0};
std::atomic<bool> g_counting{false};
std::atomic<std::size_t> g_largest_new{0};
}  // namespace

void* operator new(std::size_t n) {
  if (g_counting.load()) {
    ++g_news;
    if (n > g_largest_new.load()) g_largest_new = n;
  }
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
