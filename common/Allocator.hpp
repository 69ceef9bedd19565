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
/// settings are needed: either alone turns glibc's adaptive thresholds off and is worse. For
/// other programs (stock pimpleFoam) the same settings are GLIBC_TUNABLES=allocator_tunables().
void keep_freed_memory();

/// The same settings as a GLIBC_TUNABLES value, for programs started from here.
const char *allocator_tunables();

} // namespace fsi::common
