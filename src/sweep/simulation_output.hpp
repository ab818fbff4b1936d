#pragma once
// What `epviz simulate` writes of a run: the CSV of its samples and the JSON
// report, whose keys start with those a sweep's row has (sweep/run_record.hpp).
// The HDF5 file (h5/columns_file.hpp) and the Python module hold the same
// columns, computed here once (SampleColumns).
#include <array>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "io/atomic_file.hpp"
#include "sim/drift.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"

namespace epviz::sweep {

// The columns of a sample, in the CSV's order, and their values. a, b are
// the stereographic coordinates of gamma (absent at gamma3 = -1);
// gamma_norm_error is |gamma| - 1; extra_integral is absent without a fourth
// integral. An absent value is an empty CSV field and a NaN in arrays.
inline constexpr std::size_t kSampleColumns = 13;
const std::array<std::string, kSampleColumns>& sample_column_names();

class SampleColumns {
 public:
  explicit SampleColumns(const sim::RunSpec& spec);
  struct Row {
    std::array<double, kSampleColumns> values{};  // NaN where absent
    bool has_ab = false, has_extra = false;
  };
  Row row(const sim::Sample& s) const;

 private:
  sim::InvariantMonitor monitor_;
};

// Header: t,omega1,omega2,omega3,gamma1,gamma2,gamma3,a,b,energy,area,gamma_norm_error,extra_integral
// a, b are the stereographic coordinates of gamma (empty at gamma3 = -1);
// gamma_norm_error is |gamma| - 1; extra_integral is empty without a fourth integral.
// Written row by row as samples arrive (sim::simulate with a sink), in chunks of about 64 kB, so that memory does not grow with the number
// of samples. The header is written by the constructor; flush() writes what is
// buffered (call it before committing the file).
class SamplesCsvWriter {
 public:
  SamplesCsvWriter(const sim::RunSpec& spec, io::AtomicFile& file);
  void add(const sim::Sample& s);
  void flush();

 private:
  SampleColumns columns_;
  io::AtomicFile& file_;
  std::string buffer_;
};

nlohmann::json run_report(const sim::RunSpec& spec, const sim::RunResult& result,
                          const sim::Drifts& drift);

}  // namespace epviz::sweep
