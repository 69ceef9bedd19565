#include "hdf5/H5Handle.hpp"

#include "hdf5/H5Error.hpp"

#include <utility>

namespace fsi::hdf5 {

H5Handle::H5Handle(hid_t id, Closer closer, const std::string &what) : id_(id), closer_(closer) {
  if (id_ < 0) {
    throw_hdf5_error(what);
  }
}

H5Handle::~H5Handle() { reset(); }

H5Handle::H5Handle(H5Handle &&other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}

H5Handle &H5Handle::operator=(H5Handle &&other) noexcept {
  if (this != &other) {
    reset();
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    closer_ = other.closer_;
  }
  return *this;
}

void H5Handle::reset() {
  if (id_ >= 0 && closer_ != nullptr) {
    closer_(id_);
  }
  id_ = H5I_INVALID_HID;
}

} // namespace fsi::hdf5
