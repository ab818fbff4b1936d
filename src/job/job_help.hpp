#pragma once
// What `epviz render --help-job` prints: every key of the three job formats
// (a render job, a gallery, the figures of `epviz bench`) with its type,
// default and allowed values, read from the tables that read the jobs
// (job/schema.hpp, job/job_file.hpp), so that the help cannot drift from them.
#include <string>
#include <vector>

#include "job/schema.hpp"

namespace epviz::job {

// "number", "three numbers", "object", ...
std::string value_type_name(ValueType type);

// One key: "  camera.distance (number, default 3.2): more than 1.2, at most 100"
// then its help, indented, on the next line.
std::string key_help(const KeyInfo& key);

std::string job_keys_help();

}  // namespace epviz::job
