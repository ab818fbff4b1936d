#pragma once
// The names of epviz's temporaries, and the removal of those their writer
// left behind. A file being written goes to
//   "<name>.epviz-tmp-<machine>-<pid>"
// beside its target (atomic_file.hpp), so that a temporary is unmistakably
// epviz's (a user's "notes.txt.tmp-999" is never touched) and says which
// process wrote it: the pid is only meaningful on the same machine, which the
// machine token pins down — the host name, the boot and the PID namespace, so
// that two containers or two cluster nodes writing into one shared folder
// never take each other's live temporaries for dead ones.
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace epviz::io {

// 12 hex digits naming this process's machine (host, boot, PID namespace).
const std::string& machine_token();

// ".epviz-tmp-<machine>-<pid>", what a temporary adds to its target's name.
std::string temporary_suffix(pid_t pid, const std::string& machine = machine_token());

struct TemporaryName {
  std::string machine;
  pid_t pid = 0;
};
// The machine and pid of a temporary's name, or nullopt for any other name.
std::optional<TemporaryName> parse_temporary_name(const std::string& name);

// How long a temporary of another machine must lie unmodified before it is
// taken for dead: a writer that is alive renews its file far more often (a
// video grows with every frame; other temporaries live for one write).
inline constexpr std::chrono::hours foreign_temporary_age{24};

// Removes the temporaries in `dir` that are provably dead: of this machine
// with no such process (a run killed with SIGKILL, a crash), or of another
// machine and unmodified for `foreign_age`. This process's temporaries, live
// ones, and anything that is not a regular file are kept. Returns the paths
// removed; errors (an unreadable directory) are ignored: this is housekeeping.
std::vector<std::filesystem::path> remove_stale_temporaries(
    const std::filesystem::path& dir,
    std::filesystem::file_time_type::duration foreign_age = foreign_temporary_age);

}  // namespace epviz::io
