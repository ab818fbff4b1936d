#include "h5/columns_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "h5/handle.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/output_paths.hpp"
#include "io/temp_registry.hpp"

namespace epviz::h5 {

namespace fs = std::filesystem;

namespace {

herr_t take_first(unsigned n, const H5E_error2_t* e, void* out) {
  auto& text = *static_cast<std::string*>(out);
  if (n == 0 && e->desc) text = e->desc;
  return 0;
}

// A variable-length UTF-8 string type.
Handle text_type() {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (type.valid() &&
      (H5Tset_size(type.get(), H5T_VARIABLE) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0))
    type.reset();
  return type;
}

// "run0/label" -> ("run0", "label"); "job" -> (".", "job").
std::pair<std::string, std::string> owner_and_name(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return {".", path};
  return {path.substr(0, slash), path.substr(slash + 1)};
}

}  // namespace

std::string hdf5_error_text() {
  std::string text;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, take_first, &text);
  H5Eclear2(H5E_DEFAULT);
  return text;
}

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
  Handle file;
  Handle link_create;                          // makes the groups a dataset's path names
  std::vector<std::unique_ptr<Table>> tables;  // the root's first

  [[noreturn]] void fail(const std::string& what) const {
    std::string message = "cannot write '" + target.string() + "': HDF5 could not " + what;
    if (const std::string cause = hdf5_error_text(); !cause.empty()) message += " (" + cause + ")";
    throw io::FileWriteError(message);
  }

  void create_file();
  Handle create_dataset(const std::string& name, hid_t type, hid_t space, hid_t create,
                        hid_t access) const;
  Table& add_table(const std::string& group, const std::vector<std::string>& columns,
                   std::size_t chunk_rows);
  void set_attribute(const std::string& path, hid_t file_type, hid_t memory_type,
                     const void* value);

  // Closes every handle and removes the temporary (an uncommitted file).
  void discard() noexcept {
    tables.clear();
    link_create.reset();
    file.reset();
    hdf5_error_text();
    if (!temporary.empty()) ::unlink(temporary.c_str());
    if (cleanup_slot >= 0) io::unregister_temporary(cleanup_slot);
    cleanup_slot = -1;
  }
};

struct ColumnsFile::Table::Impl {
  const ColumnsFile::Impl* file = nullptr;
  std::size_t chunk_rows = 0;
  std::vector<std::string> names;  // paths in the file
  std::vector<Handle> datasets;
  std::vector<std::vector<double>> buffers;  // one per column, up to chunk_rows
  hsize_t written = 0;                       // rows in the datasets
  long rows = 0;                             // rows appended

  void flush() {
    const hsize_t n = buffers.empty() ? 0 : hsize_t(buffers.front().size());
    if (n == 0) return;
    const hsize_t extent[1] = {written + n};
    const hsize_t start[1] = {written};
    const hsize_t count[1] = {n};
    Handle memory(H5Screate_simple(1, count, nullptr), H5Sclose);
    if (!memory.valid()) file->fail("make a dataspace");
    for (std::size_t c = 0; c < datasets.size(); ++c) {
      const hid_t d = datasets[c].get();
      if (H5Dset_extent(d, extent) < 0) file->fail("extend the dataset '" + names[c] + "'");
      Handle space(H5Dget_space(d), H5Sclose);
      if (!space.valid() ||
          H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0 ||
          H5Dwrite(d, H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT,
                   buffers[c].data()) < 0)
        file->fail("write the dataset '" + names[c] + "'");
      buffers[c].clear();
    }
    written += n;
  }

  // Writes what is buffered and closes the datasets; false when HDF5 reports an error.
  bool close() {
    flush();
    bool closed = true;
    for (auto& d : datasets) closed = d.reset() && closed;
    datasets.clear();
    return closed;
  }
};

ColumnsFile::Table::Table(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ColumnsFile::Table::~Table() = default;

void ColumnsFile::Table::append(std::span<const double> row) {
  auto& m = *impl_;
  if (row.size() != m.buffers.size())
    throw std::invalid_argument("ColumnsFile::append: " + std::to_string(row.size()) +
                                " values for " + std::to_string(m.buffers.size()) + " columns");
  for (std::size_t c = 0; c < row.size(); ++c) m.buffers[c].push_back(row[c]);
  ++m.rows;
  if (!m.buffers.empty() && m.buffers.front().size() >= m.chunk_rows) m.flush();
}

long ColumnsFile::Table::rows() const { return impl_->rows; }

ColumnsFile::ColumnsFile(fs::path target, std::vector<std::string> columns, std::size_t chunk_rows)
    : impl_(std::make_unique<Impl>()) {
  auto& m = *impl_;
  m.target = std::move(target);
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
    m.create_file();
    m.add_table("", columns, chunk_rows);
  } catch (...) {
    m.discard();
    throw;
  }
}

void ColumnsFile::Impl::create_file() {
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  // Nobody else opens a temporary: no lock, which some file systems refuse.
  if (!access.valid() || H5Pset_file_locking(access.get(), false, true) < 0)
    fail("make the file's access properties");
  file = Handle(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), H5Fclose);
  if (!file.valid()) {
    const std::string cause = hdf5_error_text();
    throw io::FileWriteError("cannot write '" + target.string() +
                             "': " + (cause.empty() ? "HDF5 could not create it" : cause));
  }
  link_create = Handle(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  if (!link_create.valid() || H5Pset_create_intermediate_group(link_create.get(), 1) < 0)
    fail("make the links' properties");
}

Handle ColumnsFile::Impl::create_dataset(const std::string& name, hid_t type, hid_t space,
                                         hid_t create, hid_t access) const {
  Handle d(H5Dcreate2(file.get(), name.c_str(), type, space, link_create.get(), create, access),
           H5Dclose);
  if (!d.valid()) fail("create the dataset '" + name + "'");
  return d;
}

ColumnsFile::Table& ColumnsFile::Impl::add_table(const std::string& group,
                                                 const std::vector<std::string>& columns,
                                                 std::size_t chunk_rows) {
  auto t = std::make_unique<Table::Impl>();
  t->file = this;
  t->chunk_rows = chunk_rows == 0 ? 1 : chunk_rows;
  const hsize_t none[1] = {0}, unlimited[1] = {H5S_UNLIMITED};
  const hsize_t chunk[1] = {hsize_t(t->chunk_rows)};
  Handle space(H5Screate_simple(1, none, unlimited), H5Sclose);
  Handle create(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  Handle access(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose);
  // Whole chunks are written at once: no chunk cache (memory stays that of the
  // rows buffered here), and no fill values written before the data.
  if (!space.valid() || !create.valid() || !access.valid() ||
      H5Pset_chunk(create.get(), 1, chunk) < 0 ||
      H5Pset_fill_time(create.get(), H5D_FILL_TIME_NEVER) < 0 ||
      H5Pset_chunk_cache(access.get(), 0, 0, 1.0) < 0)
    fail("make the datasets' properties");
  for (const auto& column : columns) {
    const std::string name = group.empty() ? column : group + "/" + column;
    t->datasets.push_back(
        create_dataset(name, H5T_IEEE_F64LE, space.get(), create.get(), access.get()));
    t->names.push_back(name);
    t->buffers.emplace_back().reserve(t->chunk_rows);
  }
  tables.push_back(std::make_unique<Table>(std::move(t)));
  return *tables.back();
}

ColumnsFile::~ColumnsFile() {
  if (impl_ && !impl_->committed) impl_->discard();
}

void ColumnsFile::append(std::span<const double> row) { impl_->tables.front()->append(row); }

ColumnsFile::Table& ColumnsFile::add_table(const std::string& group,
                                           const std::vector<std::string>& columns,
                                           std::size_t chunk_rows) {
  return impl_->add_table(group, columns, chunk_rows);
}

void ColumnsFile::write_column(const std::string& name, std::span<const double> values) {
  auto& m = *impl_;
  const hsize_t n[1] = {hsize_t(values.size())};
  Handle space(H5Screate_simple(1, n, nullptr), H5Sclose);
  if (!space.valid()) m.fail("make the dataspace of '" + name + "'");
  Handle d = m.create_dataset(name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT);
  if (n[0] > 0 &&
      H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
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
  if (!type.valid() || !space.valid()) m.fail("make the type of the dataset '" + name + "'");
  Handle d = m.create_dataset(name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT);
  if (n[0] > 0 && H5Dwrite(d.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    m.fail("write the dataset '" + name + "'");
}

namespace {

// About 256 kB a chunk: a block of whole rows (a power of two of them, so
// that blocks of a power of two rows fill whole chunks), split along the row
// only when one row is longer than that.
void matrix_chunk(hsize_t rows, hsize_t columns, hsize_t chunk[2]) {
  constexpr hsize_t kValues = hsize_t(1) << 15;
  chunk[1] = std::max<hsize_t>(1, std::min(columns, kValues));
  hsize_t r = 1;
  while (r * 2 * chunk[1] <= kValues) r *= 2;
  chunk[0] = std::max<hsize_t>(1, std::min(rows, r));
}

}  // namespace

void ColumnsFile::create_matrix(const std::string& name, std::size_t rows, std::size_t columns) {
  auto& m = *impl_;
  const hsize_t dims[2] = {hsize_t(rows), hsize_t(columns)};
  hsize_t chunk[2];
  matrix_chunk(dims[0], dims[1], chunk);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
  Handle create(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  // Chunks never written (a run cut short) read as NaN, and none is filled
  // before it is written.
  if (!space.valid() || !create.valid() || H5Pset_chunk(create.get(), 2, chunk) < 0 ||
      H5Pset_fill_value(create.get(), H5T_NATIVE_DOUBLE, &nan) < 0 ||
      H5Pset_fill_time(create.get(), H5D_FILL_TIME_NEVER) < 0)
    m.fail("make the properties of the dataset '" + name + "'");
  m.create_dataset(name, H5T_IEEE_F64LE, space.get(), create.get(), H5P_DEFAULT);
}

void ColumnsFile::write_rows(const std::string& name, std::size_t first,
                             std::span<const double> values) {
  auto& m = *impl_;
  Handle d(H5Dopen2(m.file.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.valid()) m.fail("open the dataset '" + name + "'");
  Handle space(H5Dget_space(d.get()), H5Sclose);
  hsize_t dims[2] = {0, 0};
  if (!space.valid() || H5Sget_simple_extent_ndims(space.get()) != 2 ||
      H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0)
    m.fail("read the shape of the dataset '" + name + "'");
  if (dims[1] == 0 || values.size() % dims[1] != 0 || first + values.size() / dims[1] > dims[0])
    throw std::invalid_argument("ColumnsFile::write_rows: " + std::to_string(values.size()) +
                                " values from row " + std::to_string(first) + " do not fit '" +
                                name + "'");
  const hsize_t start[2] = {hsize_t(first), 0};
  const hsize_t count[2] = {hsize_t(values.size()) / dims[1], dims[1]};
  if (count[0] == 0) return;
  Handle memory(H5Screate_simple(2, count, nullptr), H5Sclose);
  if (!memory.valid() ||
      H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0 ||
      H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT, values.data()) <
          0)
    m.fail("write the dataset '" + name + "'");
}

void ColumnsFile::Impl::set_attribute(const std::string& path, hid_t file_type, hid_t memory_type,
                                      const void* value) {
  const auto [owner, name] = owner_and_name(path);
  Handle object(H5Oopen(file.get(), owner.c_str(), H5P_DEFAULT), H5Oclose);
  if (!object.valid()) fail("open '" + owner + "' for the attribute '" + path + "'");
  if (H5Aexists(object.get(), name.c_str()) > 0) H5Adelete(object.get(), name.c_str());
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(
      H5Acreate2(object.get(), name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  if (!space.valid() || !attribute.valid() || H5Awrite(attribute.get(), memory_type, value) < 0)
    fail("write the attribute '" + path + "'");
}

void ColumnsFile::set_attribute(const std::string& name, const std::string& text) {
  Handle type = text_type();
  if (!type.valid()) impl_->fail("make the type of the attribute '" + name + "'");
  const char* data = text.c_str();
  impl_->set_attribute(name, type.get(), type.get(), &data);
}

void ColumnsFile::set_attribute(const std::string& name, long value) {
  impl_->set_attribute(name, H5T_STD_I64LE, H5T_NATIVE_LONG, &value);
}

void ColumnsFile::set_attribute(const std::string& name, double value) {
  impl_->set_attribute(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void ColumnsFile::commit() {
  auto& m = *impl_;
  if (m.committed) return;
  bool closed = true;
  for (auto& t : m.tables) closed = t->impl_->close() && closed;
  m.tables.clear();
  closed = m.link_create.reset() && closed;
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

long ColumnsFile::rows() const { return impl_->tables.front()->rows(); }

const fs::path& ColumnsFile::target() const { return impl_->target; }

}  // namespace epviz::h5
