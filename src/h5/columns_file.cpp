#include "h5/columns_file.hpp"

#include <hdf5.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <system_error>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/output_paths.hpp"
#include "io/temp_registry.hpp"

namespace epviz::h5 {
namespace {

namespace fs = std::filesystem;

// The most specific description on HDF5's error stack ("No space left on
// device", "unable to truncate a file which is already open"), then the
// stack cleared; empty when there is none.
herr_t take_first(unsigned n, const H5E_error2_t* e, void* out) {
  auto& text = *static_cast<std::string*>(out);
  if (n == 0 && e->desc) text = e->desc;
  return 0;
}
std::string hdf5_error_text() {
  std::string text;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, take_first, &text);
  H5Eclear2(H5E_DEFAULT);
  return text;
}

// An HDF5 handle closed by its close function.
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
    const bool ok = close_(std::exchange(id_, H5I_INVALID_HID)) >= 0;
    return ok;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  herr_t (*close_)(hid_t) = nullptr;
};

}  // namespace

void check_h5_output(const std::string& option, const std::string& path) {
  if (path.empty()) return;
  if (path == "-")
    throw io::BadInput(option +
                       ": HDF5 cannot go to standard output ('-'); give a file name (*.h5)");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
    throw io::BadInput(option + ": '" + path +
                       "' is not a regular file; an HDF5 file must be one (it is written with "
                       "seeks)");
  io::check_output_file(option, path);
}

struct ColumnsFile::Impl {
  fs::path target;
  fs::path resolved;   // the file replaced (symbolic links followed)
  fs::path temporary;  // written, then renamed over `resolved`
  int cleanup_slot = -1;
  bool committed = false;
  std::size_t chunk_rows = 0;
  std::vector<std::string> names;
  Handle file;
  std::vector<Handle> datasets;
  std::vector<std::vector<double>> buffers;  // one per column, up to chunk_rows
  hsize_t written = 0;                       // rows in the datasets
  long rows = 0;                             // rows appended

  [[noreturn]] void fail(const std::string& what) const {
    std::string message = "cannot write '" + target.string() + "': HDF5 could not " + what;
    if (const std::string cause = hdf5_error_text(); !cause.empty()) message += " (" + cause + ")";
    throw io::FileWriteError(message);
  }

  void flush() {
    const hsize_t n = buffers.empty() ? 0 : hsize_t(buffers.front().size());
    if (n == 0) return;
    const hsize_t extent[1] = {written + n};
    const hsize_t start[1] = {written};
    const hsize_t count[1] = {n};
    Handle memory(H5Screate_simple(1, count, nullptr), H5Sclose);
    if (!memory.valid()) fail("make a dataspace");
    for (std::size_t c = 0; c < datasets.size(); ++c) {
      const hid_t d = datasets[c].get();
      if (H5Dset_extent(d, extent) < 0) fail("extend the dataset '" + names[c] + "'");
      Handle space(H5Dget_space(d), H5Sclose);
      if (!space.valid() ||
          H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0 ||
          H5Dwrite(d, H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT,
                   buffers[c].data()) < 0)
        fail("write the dataset '" + names[c] + "'");
      buffers[c].clear();
    }
    written += n;
  }

  // Closes every handle and removes the temporary (an uncommitted file).
  void discard() noexcept {
    datasets.clear();
    file.reset();
    hdf5_error_text();
    if (!temporary.empty()) ::unlink(temporary.c_str());
    if (cleanup_slot >= 0) io::unregister_temporary(cleanup_slot);
    cleanup_slot = -1;
  }
};

ColumnsFile::ColumnsFile(fs::path target, std::vector<std::string> columns, std::size_t chunk_rows)
    : impl_(std::make_unique<Impl>()) {
  auto& m = *impl_;
  m.target = std::move(target);
  m.names = std::move(columns);
  m.chunk_rows = chunk_rows == 0 ? 1 : chunk_rows;
  // Errors become exceptions with HDF5's own description (hdf5_error_text),
  // not a stack printed on stderr.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const io::OutputTarget resolved = io::resolve_output(m.target);
  if (resolved.kind != io::OutputKind::replace)
    throw io::FileWriteError("cannot write '" + m.target.string() +
                             "': an HDF5 file must be a regular file");
  m.resolved = resolved.path;
  m.temporary = io::temporary_path_for(m.resolved);
  io::install_temporary_cleanup();
  m.cleanup_slot = io::register_temporary(m.temporary);
  try {
    create_datasets();
  } catch (...) {
    m.discard();
    throw;
  }
}

void ColumnsFile::create_datasets() {
  auto& m = *impl_;
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  // Nobody else opens a temporary: no lock, which some file systems refuse.
  if (!access.valid() || H5Pset_file_locking(access.get(), false, true) < 0)
    m.fail("make the file's access properties");
  m.file =
      Handle(H5Fcreate(m.temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), H5Fclose);
  if (!m.file.valid()) {
    const std::string cause = hdf5_error_text();
    throw io::FileWriteError("cannot write '" + m.target.string() +
                             "': " + (cause.empty() ? "HDF5 could not create it" : cause));
  }

  const hsize_t none[1] = {0}, unlimited[1] = {H5S_UNLIMITED};
  const hsize_t chunk[1] = {hsize_t(m.chunk_rows)};
  Handle space(H5Screate_simple(1, none, unlimited), H5Sclose);
  Handle create(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  Handle access_dataset(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose);
  // Whole chunks are written at once: no chunk cache (memory stays that of the
  // rows buffered here), and no fill values written before the data.
  if (!space.valid() || !create.valid() || !access_dataset.valid() ||
      H5Pset_chunk(create.get(), 1, chunk) < 0 ||
      H5Pset_fill_time(create.get(), H5D_FILL_TIME_NEVER) < 0 ||
      H5Pset_chunk_cache(access_dataset.get(), 0, 0, 1.0) < 0)
    m.fail("make the datasets' properties");
  for (const auto& name : m.names) {
    Handle d(H5Dcreate2(m.file.get(), name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                        create.get(), access_dataset.get()),
             H5Dclose);
    if (!d.valid()) {
      const std::string cause = hdf5_error_text();
      throw io::FileWriteError("cannot write '" + m.target.string() + "': HDF5 could not create " +
                               "the dataset '" + name + "'" +
                               (cause.empty() ? "" : " (" + cause + ")"));
    }
    m.datasets.push_back(std::move(d));
    m.buffers.emplace_back().reserve(m.chunk_rows);
  }
}

ColumnsFile::~ColumnsFile() {
  if (impl_ && !impl_->committed) impl_->discard();
}

void ColumnsFile::append(std::span<const double> row) {
  auto& m = *impl_;
  if (row.size() != m.buffers.size())
    throw std::invalid_argument("ColumnsFile::append: " + std::to_string(row.size()) +
                                " values for " + std::to_string(m.buffers.size()) + " columns");
  for (std::size_t c = 0; c < row.size(); ++c) m.buffers[c].push_back(row[c]);
  ++m.rows;
  if (!m.buffers.empty() && m.buffers.front().size() >= m.chunk_rows) m.flush();
}

namespace {

// A variable-length UTF-8 string type.
Handle text_type() { return Handle(H5Tcopy(H5T_C_S1), H5Tclose); }
bool make_text(const Handle& type) {
  return type.valid() && H5Tset_size(type.get(), H5T_VARIABLE) >= 0 &&
         H5Tset_cset(type.get(), H5T_CSET_UTF8) >= 0;
}

}  // namespace

void ColumnsFile::write_column(const std::string& name, std::span<const double> values) {
  auto& m = *impl_;
  const hsize_t n[1] = {hsize_t(values.size())};
  Handle space(H5Screate_simple(1, n, nullptr), H5Sclose);
  Handle d(H5Dcreate2(m.file.get(), name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                      H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose);
  if (!space.valid() || !d.valid() ||
      (n[0] > 0 &&
       H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0))
    m.fail("write the dataset '" + name + "'");
}

void ColumnsFile::write_text_column(const std::string& name,
                                    const std::vector<std::string>& values) {
  auto& m = *impl_;
  std::vector<const char*> data;
  data.reserve(values.size());
  for (const auto& v : values) data.push_back(v.c_str());
  const hsize_t n[1] = {hsize_t(values.size())};
  Handle type = text_type();
  Handle space(H5Screate_simple(1, n, nullptr), H5Sclose);
  if (!make_text(type) || !space.valid()) m.fail("make the type of the dataset '" + name + "'");
  Handle d(H5Dcreate2(m.file.get(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Dclose);
  if (!d.valid() ||
      (n[0] > 0 && H5Dwrite(d.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0))
    m.fail("write the dataset '" + name + "'");
}

namespace {

void replace_attribute(hid_t file, const std::string& name) {
  if (H5Aexists(file, name.c_str()) > 0) H5Adelete(file, name.c_str());
}

}  // namespace

void ColumnsFile::set_attribute(const std::string& name, const std::string& text) {
  auto& m = *impl_;
  replace_attribute(m.file.get(), name);
  Handle type = text_type();
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!make_text(type) || !space.valid()) m.fail("make the type of the attribute '" + name + "'");
  Handle attribute(
      H5Acreate2(m.file.get(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  const char* data = text.c_str();
  if (!attribute.valid() || H5Awrite(attribute.get(), type.get(), &data) < 0)
    m.fail("write the attribute '" + name + "'");
}

void ColumnsFile::set_attribute(const std::string& name, long value) {
  auto& m = *impl_;
  replace_attribute(m.file.get(), name);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(
      H5Acreate2(m.file.get(), name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_LONG, &value) < 0)
    m.fail("write the attribute '" + name + "'");
}

void ColumnsFile::commit() {
  auto& m = *impl_;
  if (m.committed) return;
  m.flush();
  bool closed = true;
  for (auto& d : m.datasets) closed = d.reset() && closed;
  m.datasets.clear();
  closed = m.file.reset() && closed;
  if (!closed) m.fail("close the file");
  if (std::rename(m.temporary.c_str(), m.resolved.c_str()) != 0) {
    const int error = errno;
    throw io::FileWriteError("cannot write '" + m.target.string() +
                             "': " + std::system_category().message(error));
  }
  m.committed = true;
  if (m.cleanup_slot >= 0) io::unregister_temporary(m.cleanup_slot);
  m.cleanup_slot = -1;
}

long ColumnsFile::rows() const { return impl_->rows; }

const fs::path& ColumnsFile::target() const { return impl_->target; }

}  // namespace epviz::h5
