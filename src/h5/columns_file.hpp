#pragma once
// An HDF5 file of named columns (Debian's libhdf5, through its C API, which no
// other header sees): one float64 dataset per column at the file's root,
// chunked and extended as rows come, so that memory stays bounded however
// many rows a run writes; text attributes on the root (JSON, a version).
// Several runs in one file (a render's) each get a group of such columns
// (add_table), and an ensemble a 2-D dataset per quantity written a block of
// members at a time (create_matrix, write_rows).
//
// Names are paths: "t" at the root, "run0/t" in the group run0 (made with
// its parents when a dataset is created in it); an attribute "run0/label" is
// the attribute "label" of run0.
//
// The file is written as every output of epviz is (io/atomic_file.hpp): under
// a temporary name beside the target (io/temp_name.hpp), registered for
// removal on SIGINT/SIGTERM (io/temp_registry.hpp), and renamed over the
// target on commit(). Destroyed without commit() (an exception), the
// temporary is removed and the target left as it was. HDF5 needs a file it
// can seek in: a target that exists and is not a regular file (/dev/null, a
// FIFO) is refused, as is "-" (check_h5_output, before any work).
#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace epviz::h5 {

// `path`, given by `option` ("--h5"), can become an HDF5 file: not "-", not an
// existing file that is not a regular one, and writable as
// io::check_output_file checks. Empty: not given, fine. Throws io::BadInput
// naming the option.
void check_h5_output(const std::string& option, const std::string& path);

class ColumnsFile {
 public:
  static constexpr std::size_t kChunkRows = 16384;

  // Creates the temporary with one empty, extendible dataset per name, each
  // chunked by `chunk_rows` rows (none: only whole columns are written).
  // Throws io::FileWriteError naming the target.
  ColumnsFile(std::filesystem::path target, std::vector<std::string> columns,
              std::size_t chunk_rows = kChunkRows);
  ~ColumnsFile();
  ColumnsFile(const ColumnsFile&) = delete;
  ColumnsFile& operator=(const ColumnsFile&) = delete;

  // Columns that grow together, one row at a time: rows are kept until a
  // chunk is full, then written.
  class Table {
   public:
    ~Table();
    // One value per column, in the order the columns were named.
    void append(std::span<const double> row);
    long rows() const;

    struct Impl;  // columns_file.cpp's
    explicit Table(std::unique_ptr<Impl> impl);

   private:
    friend class ColumnsFile;
    std::unique_ptr<Impl> impl_;
  };

  // The root's columns (the constructor's).
  void append(std::span<const double> row);
  // Columns of their own in `group` ("run1"), as the root's; the table lives
  // as long as the file.
  Table& add_table(const std::string& group, const std::vector<std::string>& columns,
                   std::size_t chunk_rows = kChunkRows);
  // A whole column written at once, beside the appended ones (a table built
  // before it is written, such as a sweep's rows): a float64 dataset, or one
  // of variable-length UTF-8 strings.
  void write_column(const std::string& name, std::span<const double> values);
  void write_text_column(const std::string& name, const std::vector<std::string>& values);
  // A float64 dataset of `rows` x `columns` (an ensemble's members by their
  // samples), chunked in blocks of whole rows, written a block at a time by
  // write_rows: rows [first, first + values.size() / columns), row-major.
  // What is never written reads as NaN.
  void create_matrix(const std::string& name, std::size_t rows, std::size_t columns);
  void write_rows(const std::string& name, std::size_t first, std::span<const double> values);
  // A variable-length UTF-8 string attribute (replaced if set before).
  void set_attribute(const std::string& name, const std::string& text);
  // An integer attribute, and a float64 one.
  void set_attribute(const std::string& name, long value);
  void set_attribute(const std::string& name, double value);
  // Writes what is buffered, closes the file and renames it over the target.
  void commit();

  long rows() const;
  const std::filesystem::path& target() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace epviz::h5
