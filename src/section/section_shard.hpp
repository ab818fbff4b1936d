#pragma once
// A shard of a section (`epviz section FILE --shard I/N`, or the array job's
// environment, as for sweeps): a contiguous range of the section's runs
// (section_run_of: method by method, orbits in order), whose crossings go to
// "<csv>.shard-I-of-N.csv" beside the section's CSV, with a manifest of kind
// "section" that `epviz merge` reads (section_merge.hpp). The shard's lock,
// manifest and states are those of every shard (src/shard).
#include <optional>
#include <string>

#include "section/section_job.hpp"
#include "shard/rows_shard.hpp"
#include "shard/shard_lock.hpp"

namespace epviz::section {

// `runs`: of the whole section (run_count); `jobs`: the -j given ("" when
// not), which the rerun command repeats.
shard::RowsShard plan_section_shard(const SectionJob& job, long runs, const shard::ShardSpec& spec,
                                    const std::string& jobs);

}  // namespace epviz::section
