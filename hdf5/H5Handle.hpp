#pragma once
// RAII owner of one HDF5 identifier (file, group, dataset, dataspace, attribute, type,
// property list): closes it with the matching H5?close function exactly once.

#include <hdf5.h>

#include <string>

namespace fsi::hdf5 {

class H5Handle {
public:
  using Closer = herr_t (*)(hid_t);

  H5Handle() = default;
  /// Takes ownership of `id`; throws std::runtime_error("<what>: ...") when `id` is negative
  /// (the HDF5 call that produced it failed).
  H5Handle(hid_t id, Closer closer, const std::string &what);
  ~H5Handle();

  H5Handle(const H5Handle &) = delete;
  H5Handle &operator=(const H5Handle &) = delete;
  H5Handle(H5Handle &&other) noexcept;
  H5Handle &operator=(H5Handle &&other) noexcept;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Closes now (no-op when empty).
  void reset();

  static H5Handle file(hid_t id, const std::string &what) { return {id, H5Fclose, what}; }
  static H5Handle group(hid_t id, const std::string &what) { return {id, H5Gclose, what}; }
  static H5Handle dataset(hid_t id, const std::string &what) { return {id, H5Dclose, what}; }
  static H5Handle dataspace(hid_t id, const std::string &what) { return {id, H5Sclose, what}; }
  static H5Handle attribute(hid_t id, const std::string &what) { return {id, H5Aclose, what}; }
  static H5Handle datatype(hid_t id, const std::string &what) { return {id, H5Tclose, what}; }
  static H5Handle plist(hid_t id, const std::string &what) { return {id, H5Pclose, what}; }

private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

} // namespace fsi::hdf5
