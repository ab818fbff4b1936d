#pragma once
// Inside h5/ only (it includes hdf5.h, which no other module sees): an HDF5
// identifier closed by its close function, and the description HDF5 gives of
// its last error.
#include <hdf5.h>

#include <string>
#include <utility>

namespace epviz::h5 {

// The most specific description on HDF5's error stack ("No space left on
// device", "unable to truncate a file which is already open"), then the
// stack cleared; empty when there is none.
std::string hdf5_error_text();

class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), close_(o.close_) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, H5I_INVALID_HID);
      close_ = o.close_;
    }
    return *this;
  }
  ~Handle() { reset(); }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now; false when HDF5 reports an error.
  bool reset() {
    if (id_ < 0) return true;
    return close_(std::exchange(id_, H5I_INVALID_HID)) >= 0;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  herr_t (*close_)(hid_t) = nullptr;
};

}  // namespace epviz::h5
