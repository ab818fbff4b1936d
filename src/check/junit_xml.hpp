#pragma once
// JUnit XML, the test report format GitLab, Jenkins and GitHub Actions
// (through report actions) read: <testsuites> with one <testsuite> per job and
// one <testcase> per checked frame; a failing frame carries a <failure> with
// its message.
#include <string>
#include <string_view>
#include <vector>

#include "check/frame_result.hpp"

namespace epviz::check {

// Text safe inside an XML element or a double-quoted attribute.
std::string xml_escape(std::string_view text);

// Jobs appear in the order of their first frame in `results`.
std::string junit_xml(const std::vector<FrameResult>& results, double seconds);

}  // namespace epviz::check
