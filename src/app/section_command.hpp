#pragma once
// `epviz section SECTION.json`: a Poincaré section, its crossings as CSV
// (docs/sections.md), whole or one shard of it.
#include <functional>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "io/print_size.hpp"
#include "section/section_merge.hpp"

namespace epviz::app {

std::function<int()> add_section_command(cli::Command app);

// A section's shards joined by `epviz merge`: writes its CSV and draws its
// PNG and SVG, as an unsharded run does, and with `h5` (a path) the
// crossings as HDF5 too, as `epviz section --h5` writes them. `print`: the
// merge's --figure-width, --font-size, --dpi, over the section file's keys.
void write_merged_section(const section::MergedSection& merged, const std::string& gl,
                          const std::string& h5 = "", const io::PrintSizeText& print = {});
// Throws io::BadInput when `print` and the section file's keys make no print
// size (write_merged_section would refuse them after other files are written).
void check_merged_section(const section::MergedSection& merged, const io::PrintSizeText& print);

}  // namespace epviz::app
