#pragma once
// glibc's allocator, tuned for solvers that allocate and free the same large blocks every time
// step (OpenFOAM's temporary fields, the coupling's array frames).

namespace fsi::common {

/// Keeps freed blocks of up to 32 MiB in the process's heap, and up to 256 MiB of free heap
/// top, instead of handing them back to the kernel. With glibc's defaults such blocks are
/// unmapped (or trimmed) when freed and page-faulted in again at the next step, which on a
/// virtualised machine made an OpenFOAM step of 296k cells about 2x slower (850 against 420 ms)
/// and a coupled step of 10^5 points 44 ms instead of 7 (docs/verification.md). Call it at the
/// start of main, before the solver allocates; calling it again does nothing more. Both
/// settings are needed: either alone turns glibc's adaptive thresholds off and is worse. Stock
/// OpenFOAM programs started by our scripts get the same values through GLIBC_TUNABLES
/// (python/fsi/fsi_launch.py, ALLOCATOR_TUNABLES).
void keep_freed_memory();

} // namespace fsi::common
