#include "hdf5/H5FileAccess.hpp"

#include "hdf5/H5Error.hpp"

namespace fsi::hdf5 {

H5Handle file_access_without_locking(const std::string &what) {
  H5Handle access = H5Handle::plist(H5Pcreate(H5P_FILE_ACCESS), what);
#if H5_VERSION_GE(1, 10, 7)
  check_hdf5(H5Pset_file_locking(access.get(), false, true), what);
#endif
  return access;
}

} // namespace fsi::hdf5
