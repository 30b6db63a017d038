#include "allocation_counter.hpp"

#include <cstdlib>
#include <new>

namespace {
thread_local bool t_armed = false;
thread_local std::uint64_t t_count = 0;

void* counted_alloc(std::size_t n) {
  if (t_armed) ++t_count;
  void* p = std::malloc(n == 0 ? 1 : n);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}
} // namespace

namespace hilrig::test {
void arm_allocation_counter() {
  t_count = 0;
  t_armed = true;
}
std::uint64_t disarm_allocation_counter() {
  t_armed = false;
  return t_count;
}
} // namespace hilrig::test

void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  if (t_armed) ++t_count;
  return std::malloc(n == 0 ? 1 : n);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
