#pragma once
// What a manifest may say. A merge reads manifests that other machines, other
// users or a repository wrote, so every field it opens, writes, runs or
// prints is held to the shape epviz itself writes: the merge's inputs and
// outputs stay inside its folders, and its advice is a command epviz would
// have written. Each function returns what is wrong, or "" when the value is
// lawful, for read_manifest to name with the file and key.
#include <string>
#include <vector>

namespace epviz::shard {

// The merged output: a plain file name in the output folder, or "" for none.
std::string output_name_problem(const std::string& name);

// A file the shard wrote: relative to the manifest's folder and inside it.
std::string file_path_problem(const std::string& path);

// For a render, what the merge hands to ffmpeg or checks as frames: the
// segments of a video `output` end in its (video) extension, PNG frames in ".png".
std::string render_file_problem(const std::string& path, const std::string& output);

// The batch's hash: hex digits, as shard/checksum writes them.
std::string hash_problem(const std::string& hash);

// Text echoed in messages and advice (the source): one line of printable characters.
std::string text_problem(const std::string& text);

// The command that ran the shard: "epviz KIND SOURCE" followed by options of
// that kind's command, each with one value.
std::string command_problem(const std::vector<std::string>& command, const std::string& kind,
                            const std::string& source);

}  // namespace epviz::shard
