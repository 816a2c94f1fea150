#pragma once
/// \file allocator.hpp
/// The applications' choice of how the C library's allocator keeps memory (the core leaves it to
/// them: a library does not tune its host's allocator).

namespace pagor::app {

/// Keeps freed memory in the process for the next allocation instead of handing it back to the
/// system at once: blocks up to 32 MiB come from the heap (not a mapping of their own, unmapped
/// on free), and the heap's top is trimmed only past 1 GiB free. A pair's clouds, grids and
/// graphs are freed and allocated again for the next pair (or stage), and a page first touched
/// costs a fault, dear in a virtual machine: on the KITTI dev pairs, 7,900 faults fell to 4,700
/// and the bench's process time by a third. Memory stays at the run's peak until it exits.
/// Does nothing where the C library is not glibc.
void keep_freed_memory();

}  // namespace pagor::app
