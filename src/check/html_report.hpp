#pragma once
// The HTML report of `epviz check --report DIR`: DIR/index.html, one page with
// no outside resources (the images are files next to it), listing every frame
// and showing golden, actual and diff side by side for each failing one.
#include <string>
#include <vector>

#include "check/frame_result.hpp"

namespace epviz::check {

struct ReportHeader {
  std::string
      tolerance;  // "a pixel differs above 4/255 in any channel; a frame fails above 1 % of its pixels"
  std::string renderer;  // GL renderer and version of this run
};

std::string html_report(const std::vector<FrameResult>& results, const ReportHeader& header);

}  // namespace epviz::check
