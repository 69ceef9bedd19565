#include "structure_solver/output/H5FileAccess.hpp"

#include "structure_solver/output/H5Error.hpp"

namespace fsi::structure::output {

H5Handle file_access_without_locking(const std::string &what) {
  H5Handle access = H5Handle::plist(H5Pcreate(H5P_FILE_ACCESS), what);
#if H5_VERSION_GE(1, 10, 7)
  check_hdf5(H5Pset_file_locking(access.get(), false, true), what);
#endif
  return access;
}

} // namespace fsi::structure::output
