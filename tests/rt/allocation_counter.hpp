#pragma once
// Counts heap allocations made by the calling thread while armed: the proof that the RT
// loop does not allocate. The global operator new/delete of this test binary are replaced
// in allocation_counter.cpp.
#include <cstdint>

namespace hilrig::test {
void arm_allocation_counter();
std::uint64_t disarm_allocation_counter(); // returns allocations seen while armed
} // namespace hilrig::test
