#pragma once
// Temporaries that must not outlive the process. A file being written
// atomically (temp_name.hpp, atomic_file.hpp) or by an ffmpeg child is
// registered here while it exists; on SIGINT or SIGTERM the handler removes
// every registered temporary, kills registered children (so that they cannot
// write the file again), and re-raises the signal with its default action, so
// the process still dies of that signal. SIGKILL cannot be caught: what it
// leaves behind is removed by remove_stale_temporaries() (temp_name.hpp) on
// the next run.
//
// The table has a fixed size and the handler uses only async-signal-safe calls
// (unlink, kill, signal, raise); paths are copied into fixed buffers when
// registered, so the handler never touches the heap.
#include <sys/types.h>

#include <cstddef>
#include <filesystem>

namespace epviz::io {

// Installs the SIGINT/SIGTERM handlers (once; later calls do nothing). A
// signal that is ignored when this is first called (e.g. SIGINT of a
// background job in a non-interactive shell) stays ignored.
void install_temporary_cleanup();

// Registers `path` (and optionally a child process to kill first). Returns a
// slot to pass to unregister_temporary, or -1 when the table is full or the
// path too long: the file then simply is not cleaned up by a signal.
int register_temporary(const std::filesystem::path& path, pid_t child = -1);
void unregister_temporary(int slot) noexcept;
// The registered child has been reaped: its pid may be reused, never kill it.
void forget_child(int slot) noexcept;

// How many temporaries are registered now (for tests).
std::size_t registered_temporaries();

}  // namespace epviz::io
