#pragma once
// Quoting for a POSIX shell, for the command lines epviz prints or writes into
// scripts (the command that makes new goldens, the command that reruns a shard).
#include <string>

namespace epviz::io {

// `word` as one word of a POSIX shell: as it is when it is plain (ASCII
// letters, digits and _-./=:,+@%), else in single quotes, a quote inside
// written '\''. The empty word is ''.
std::string shell_quote(const std::string& word);

}  // namespace epviz::io
