#pragma once
// The simulation fields as command-line text (`epviz simulate --inertia 1,1,2
// --t-end 40`): one value per field of the field table, converted and checked
// against the field's range as the job's key is, each named by its option.
// The options themselves are defined where CLI11 is (app/simulation_fields).
#include <string>
#include <vector>

#include "job/document.hpp"
#include "job/fields.hpp"

namespace epviz::job {

// The values typed, one per field of simulation_field_table() in its order;
// text empty: not given (the command line refuses an empty value itself).
struct SimulationOptions {
  struct Value {
    std::string text;  // fields that take a value
    bool set = false;  // flags
  };
  std::vector<Value> values = std::vector<Value>(simulation_field_table().size());
};

// The fields the options give, each converted and its origin the option's
// flag ("--inertia"); throws io::BadInput naming the option for a value that
// is not a number, a vector, ... or is out of the field's range.
SimulationFields fields_from_options(const SimulationOptions& options);

}  // namespace epviz::job
