#pragma once
// `epviz section SECTION.json`: a Poincaré section, its crossings as CSV
// (docs/sections.md), whole or one shard of it.
#include <functional>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "section/section_merge.hpp"

namespace epviz::app {

std::function<int()> add_section_command(cli::Command app);

// A section's shards joined by `epviz merge`: writes its CSV and draws its
// PNG and SVG, as an unsharded run does.
void write_merged_section(const section::MergedSection& merged, const std::string& gl);

}  // namespace epviz::app
