#pragma once
// File-access properties of the results file. HDF5 >= 1.10 locks a file opened for writing,
// so by default nobody could look at a running simulation's results (h5py, ParaView fail with
// "unable to lock file"). The writer flushes a complete step before it starts the next, so we
// open without the lock: other processes may read the steps saved so far while the run goes on.

#include "hdf5/H5Handle.hpp"

#include <string>

namespace fsi::hdf5 {

/// A file-access property list with HDF5 file locking off (where the library supports it).
H5Handle file_access_without_locking(const std::string &what);

} // namespace fsi::hdf5
