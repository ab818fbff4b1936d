#include "io/video_join.hpp"

#include "io/atomic_file.hpp"
#include "io/subprocess.hpp"
#include "io/video_writer.hpp"

namespace epviz::io {

namespace fs = std::filesystem;

void join_video_segments(const std::vector<fs::path>& segments, const fs::path& out) {
  const std::string name = out.filename().string();
  const fs::path list = out.parent_path() / (name + ".segments.txt");
  std::string text;
  for (const auto& s : segments) {
    std::string quoted;  // the concat list's quoting: ' becomes '\''
    for (char c : fs::absolute(s).string())
      quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    text += "file '" + quoted + "'\n";
  }
  write_file_atomically(list, text);
  const fs::path tmp = out.parent_path() / (".merging-" + name);
  const auto r =
      run_process({"ffmpeg", "-hide_banner", "-loglevel", "error", "-nostdin", "-y", "-f", "concat",
                   "-safe", "0", "-i", list.string(), "-c", "copy", tmp.string()});
  fs::remove(list);
  if (!r.status.success()) {
    fs::remove(tmp);
    throw VideoError("ffmpeg could not join the segments into " + out.string() + ": " +
                     r.status.describe() + ": " + r.err.substr(0, 300));
  }
  fs::rename(tmp, out);
}

}  // namespace epviz::io
