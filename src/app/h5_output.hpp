#pragma once
// What every HDF5 file of the command line carries beside its columns
// (h5/columns_file.hpp): epviz's version and the SIMD path of this process
// (numerics/simd_path.hpp), and the simulation fields as given.
#include <nlohmann/json.hpp>

#include "h5/columns_file.hpp"
#include "job/document.hpp"

namespace epviz::app {

// Attributes "epviz_version" and "simd_path".
void write_provenance(h5::ColumnsFile& file);

// The fields that were given (on the command line or in a job file), as a
// job's "simulation" object would hold them.
nlohmann::json given_fields_json(const job::SimulationFields& fields);

}  // namespace epviz::app
