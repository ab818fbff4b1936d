#pragma once
// `epviz merge DIR`: the shards of sweeps and renders found in DIR (by their
// manifests) checked and joined: sweep rows concatenated in point order,
// video segments joined (ffmpeg's concat demuxer, no re-encoding), and a
// sweep's atlas figures drawn (docs/cluster.md).
#include <functional>

#include "app/cli.hpp"

namespace epviz::app {

std::function<int()> add_merge_command(cli::Command app);

}  // namespace epviz::app
