#include "hdf5/H5Error.hpp"

#include <stdexcept>
#include <vector>

namespace fsi::hdf5 {
namespace {

herr_t keep_innermost_description(unsigned n, const H5E_error2_t *error, void *client_data) {
  auto *description = static_cast<std::string *>(client_data);
  if (n == 0 && error->desc != nullptr) {
    *description = error->desc;
  }
  return 0;
}

std::string innermost_hdf5_message() {
  std::string description;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_innermost_description, &description);
  H5Eclear2(H5E_DEFAULT);
  return description.empty() ? std::string("HDF5 call failed") : description;
}

} // namespace

void silence_hdf5_error_printing() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

void throw_hdf5_error(const std::string &what) {
  throw std::runtime_error(what + ": " + innermost_hdf5_message());
}

void check_hdf5(herr_t status, const std::string &what) {
  if (status < 0) {
    throw_hdf5_error(what);
  }
}

std::string hdf5_object_name(hid_t object_id) {
  const ssize_t length = H5Iget_name(object_id, nullptr, 0);
  if (length <= 0) {
    H5Eclear2(H5E_DEFAULT);
    return "<unnamed object>";
  }
  std::vector<char> buffer(static_cast<std::size_t>(length) + 1, '\0');
  H5Iget_name(object_id, buffer.data(), buffer.size());
  return std::string(buffer.data());
}

} // namespace fsi::hdf5
