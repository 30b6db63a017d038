#pragma once

namespace hilrig::cli {

// `hilrig run`'s allocator policy: freed heap is kept for the next run instead of going back
// to the kernel. A run's large buffers (the trace's samples, the edge and scan buffers) are
// freed when it ends and allocated again by the next run or probe; with glibc's defaults each
// comes from a fresh mmap (or regrows a trimmed heap), so every page of it faults again, and a
// page fault costs 30-40 us of system CPU on a virtual machine (docs/PERFORMANCE.md, "The
// kernel's share"). A test rig's process is short-lived or holds its peak anyway, so keeping
// the peak is the better trade. Returns false where the allocator is not glibc's (the
// sanitizer builds replace malloc), and changes nothing there.
bool keep_freed_heap();

} // namespace hilrig::cli
