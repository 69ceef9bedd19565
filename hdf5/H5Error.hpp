#pragma once
// Turning HDF5 failures into exceptions. HDF5 prints its error stack to stderr by default;
// the results module silences that and reports the innermost HDF5 message in the exception.

#include <hdf5.h>

#include <string>

namespace fsi::hdf5 {

/// Stop HDF5 from printing its error stack (process-wide, idempotent).
void silence_hdf5_error_printing();

/// Throws std::runtime_error("<what>: <innermost HDF5 message>") and clears the HDF5 stack.
[[noreturn]] void throw_hdf5_error(const std::string &what);

/// Throws via throw_hdf5_error() when an HDF5 call returned a negative status.
void check_hdf5(herr_t status, const std::string &what);

/// The path of an HDF5 object inside its file ("/structures/sheet/position_m").
std::string hdf5_object_name(hid_t object_id);

} // namespace fsi::hdf5
