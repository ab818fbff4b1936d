#pragma once
// `epviz merge` of a section's shards (section_shard.hpp): their crossings
// joined into the CSV an unsharded run writes, byte for byte, and the
// results to draw its pictures from. The merge reads the section file again
// (the manifests' source): its methods name the CSV's runs and its keys the
// pictures, so it must be the file the shards ran.
#include <filesystem>
#include <vector>

#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "shard/batch.hpp"

namespace epviz::section {

struct MergedSection {
  SectionJob job;                    // csv, png, svg: where the merge writes them
  std::vector<OrbitResult> results;  // every run, in order; crossings from the CSV
  std::string csv_text;              // the joined CSV
};

// Reads and checks the complete batch `b` of DIR `dir`: the section file
// unchanged since the shards ran, each shard's CSV its header and then rows
// of its own runs only. Sets the outputs to their file names in `out_dir`.
// Throws io::BadInput naming the file (and line). Writes nothing.
MergedSection read_section_shards(const shard::Batch& b, const std::filesystem::path& dir,
                                  const std::filesystem::path& out_dir);

}  // namespace epviz::section
