#pragma once
// Checks of every output path before any work: a run that cannot write its
// results stops at once with exit 2 and writes nothing, instead of failing
// after the integration or the rendering.
#include <filesystem>
#include <string>

namespace epviz::app {

// `path` names one output file (given by `option`, e.g. "--csv"): "-"
// (standard output), a file that exists or can be created in an existing,
// writable directory, or an existing non-regular file that can be opened for
// writing (/dev/null, a FIFO). A directory is refused. Empty: not given, fine.
// Throws io::BadInput naming the option.
void check_output_file(const std::string& option, const std::string& path);

// `dir` is an output directory (named by `what`: "--out" or "job.json: output.dir"):
// an existing writable directory, or one that can be created (its first
// existing ancestor is a writable directory). Throws io::BadInput.
void check_output_dir(const std::string& what, const std::filesystem::path& dir);

// `name` becomes part of file names (output.name): not empty, not "." or "..",
// no '/', NUL or control characters, and short enough for the file system
// with the frame number and extension added. Throws io::BadInput naming `what`.
void check_file_name(const std::string& what, const std::string& name);

}  // namespace epviz::app
