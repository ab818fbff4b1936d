#pragma once
// JUnit XML, the test report format GitLab, Jenkins and GitHub Actions
// (through report actions) read: <testsuites> with one <testsuite> per job and
// one <testcase> per checked frame, with the time the frame took; a failing
// frame carries a <failure> with its message. The report images of a frame
// are named in its <system-out> as [[ATTACHMENT|path]], the line Jenkins'
// JUnit Attachments plugin and GitLab's test report read.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "check/frame_result.hpp"

namespace epviz::check {

// Text safe inside an XML element or a double-quoted attribute.
std::string xml_escape(std::string_view text);

// Jobs appear in the order of their first frame in `results`. `seconds`: the
// whole run. `report_dir`: where the results' images are (as the user named
// it, so that a relative path stays relative to the CI job's directory).
std::string junit_xml(const std::vector<FrameResult>& results, double seconds,
                      const std::filesystem::path& report_dir = {});

}  // namespace epviz::check
