#pragma once
// Checks of every output path before any work: a run that cannot write its
// results stops at once with exit 2 and writes nothing, instead of failing
// after the integration or the rendering.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace epviz::io {

// `path` names one output file (given by `option`, e.g. "--csv"): "-"
// (standard output), a file that exists or can be created in an existing,
// writable directory, or an existing non-regular file that can be opened for
// writing (/dev/null, a FIFO). A directory is refused. Empty: not given, fine.
// Throws BadInput naming the option.
void check_output_file(const std::string& option, const std::string& path);

// Files a run reads or writes, each with what names it in a message: the
// option ("--csv") or the file and key ("s.json: key 'png'").
using NamedPaths = std::vector<std::pair<std::string, std::string>>;

// The one check every command makes before any work that no output replaces
// what the run reads or writes: throws BadInput, naming both, when an output
// is one of the inputs or two outputs are one file. Files are compared by
// identity, not by name: an existing file by device and inode (another
// spelling, a symbolic or a hard link to it is the same file), one not there
// yet by its absolute path with links resolved and "."/".." removed. Empty
// paths, "-" (standard output) and character devices (/dev/null, a
// terminal), which nothing replaces, are skipped.
void require_separate_files(const NamedPaths& inputs, const NamedPaths& outputs);

// `dir` is an output directory (named by `what`: "--out" or "job.json: output.dir"):
// an existing writable directory, or one that can be created (its first
// existing ancestor is a writable directory). Throws BadInput.
void check_output_dir(const std::string& what, const std::filesystem::path& dir);

// `name` becomes part of file names (output.name): not empty, not "." or "..",
// no '/', NUL or control characters, and short enough for the file system
// with the frame number and extension added. Throws BadInput naming `what`.
void check_file_name(const std::string& what, const std::string& name);

// A FIFO given as an output file (`option`: "--junit") that is written at the
// end of a run: opened now without blocking, it fails when nobody reads it
// (rather than hanging after the whole run); the descriptor is held until the
// run ends so that the reader does not see the end of the stream before the
// output comes. Anything but a FIFO is left alone. Throws BadInput.
class FifoReaderCheck {
 public:
  FifoReaderCheck(const std::string& option, const std::string& target);
  ~FifoReaderCheck();
  FifoReaderCheck(const FifoReaderCheck&) = delete;
  FifoReaderCheck& operator=(const FifoReaderCheck&) = delete;

 private:
  int fd_ = -1;
};

// Creates the output folder `dir` (given by `option`) and makes sure a file
// can be made in it (a directory like /proc/self exists but takes no files).
// Throws BadInput.
void make_output_folder(const std::string& option, const std::string& dir);

}  // namespace epviz::io
