#include "job/job_file.hpp"

#include <string_view>

#include "job/schema_entries.hpp"

namespace epviz::job {

bool is_other_command_file(const std::filesystem::path& file) {
  const auto name = file.filename().string();
  for (const std::string_view suffix : {".sweep.json", ".section.json"})
    if (name.size() > suffix.size() && name.ends_with(suffix)) return true;
  return false;
}

using namespace entries;

namespace {

RenderJob read_single(const nlohmann::json& j, const std::filesystem::path& file) {
  JobDocument d = read_job(j, file.string());
  RenderJob job{file, std::move(d.simulation), std::move(d.runs), std::move(d.scene),
                std::move(d.output)};
  if (job.output.name.empty()) job.output.name = job.output.video ? file.stem().string() : "frame";
  return job;
}

// The gallery's "videos": none, or a video format's name.
std::vector<std::string> video_choices() {
  std::vector<std::string> names{"none"};
  for (const auto f : io::video_formats) names.emplace_back(io::video_format_name(f));
  return names;
}

using Gallery = Entry<GalleryJob>;
using Bench = Entry<BenchFiguresJob>;

Gallery tile_key(const char* key, int GalleryJob::*m, long lo, long hi, std::string help) {
  return {{key, ValueType::integer, std::to_string(GalleryJob{}.*m),
           std::to_string(lo) + " to " + std::to_string(hi), std::move(help)},
          [=](io::ObjectReader& r, GalleryJob& g) {
            if (auto v = r.integer(key, lo, hi)) g.*m = int(*v);
          },
          [=](const GalleryJob& g, Json& j) { j[key] = g.*m; }};
}

// "dir": where the outputs go, relative to the current directory.
KeyInfo dir_info(const std::filesystem::path& default_dir) {
  return {"dir", ValueType::text, default_dir.string(), "",
          "output directory, relative to the current directory"};
}

const std::vector<Gallery>& gallery_entries() {
  static const std::vector<Gallery> entries{
      {{"jobs", ValueType::text, "", "a non-empty array of job file names",
        "the single jobs to tile, relative to the gallery file (required)"},
       [](io::ObjectReader& r, GalleryJob& g) {
         const auto* list = r.raw("jobs");
         if (list == nullptr || !list->is_array() || list->empty())
           r.fail("jobs", "expected a non-empty array of job file names");
         for (std::size_t i = 0; i < list->size(); ++i) {
           const auto& item = (*list)[i];
           if (!item.is_string())
             r.fail("jobs", "item " + std::to_string(i) + ": expected a job file name");
           const auto sub = g.file.parent_path() / item.get<std::string>();
           g.jobs.push_back(read_single(io::read_json_file(sub), sub));
         }
       },
       [](const GalleryJob& g, Json& j) {
         Json names = Json::array();
         for (const auto& job : g.jobs)
           names.push_back(job.file.lexically_relative(g.file.parent_path()).string());
         j["jobs"] = std::move(names);
       }},
      {{"tile", ValueType::object, "", "", "the size of each job's tile and their arrangement"},
       {},
       {},
       {tile_key("width", &GalleryJob::tile_width, 16, 4096, "tile width in pixels"),
        tile_key("height", &GalleryJob::tile_height, 16, 4096, "tile height in pixels"),
        tile_key("columns", &GalleryJob::columns, 1, 16, "tiles per row"),
        {{"at", ValueType::number, "0.6", "0 to 1",
          "which frame of each job to tile, as a fraction of its run"},
         [](io::ObjectReader& r, GalleryJob& g) {
           if (auto v = r.number_in("at", 0, 1, "a fraction of the run from 0 to 1")) g.at = *v;
         },
         [](const GalleryJob& g, Json& j) { j["at"] = g.at; }}}},
      {{"videos", ValueType::choice, "none", joined(video_choices()),
        "also a video of each job in this format"},
       [](io::ObjectReader& r, GalleryJob& g) {
         if (auto v = r.choice("videos", video_choices()))
           g.videos = io::parse_video_format(*v);  // none: no video
       },
       [](const GalleryJob& g, Json& j) {
         j["videos"] = g.videos ? std::string(io::video_format_name(*g.videos)) : "none";
       }},
      {{"grid_video", ValueType::boolean, "false", "true, false",
        "also one MP4 of every job tiled, frame by frame (grid.mp4)"},
       [](io::ObjectReader& r, GalleryJob& g) {
         if (auto v = r.boolean("grid_video")) g.grid_video = *v;
       },
       [](const GalleryJob& g, Json& j) { j["grid_video"] = g.grid_video; }},
      {dir_info(GalleryJob{}.dir),
       [](io::ObjectReader& r, GalleryJob& g) {
         if (auto v = r.string("dir")) g.dir = *v;
       },
       [](const GalleryJob& g, Json& j) { j["dir"] = g.dir.string(); }},
  };
  return entries;
}

Bench bench_quick() {
  return {{"quick", ValueType::boolean, "false", "true, false",
           "the short study of epviz bench --quick"},
          [](io::ObjectReader& r, BenchFiguresJob& b) {
            if (auto v = r.boolean("quick")) b.quick = *v;
          },
          [](const BenchFiguresJob& b, Json& j) { j["quick"] = b.quick; }};
}

Bench bench_cases() {
  return {{"cases", ValueType::text, "", "an array of case names",
           "the presets of the work-precision and drift studies (default: all)"},
          [](io::ObjectReader& r, BenchFiguresJob& b) {
            const auto* cases = r.raw("cases");
            if (cases == nullptr) return;
            if (!cases->is_array()) r.fail("cases", "expected an array of case names");
            for (const auto& c : *cases) {
              if (!c.is_string()) r.fail("cases", "expected an array of case names");
              b.cases.push_back(c.get<std::string>());
            }
          },
          [](const BenchFiguresJob& b, Json& j) {
            if (!b.cases.empty()) j["cases"] = b.cases;
          }};
}

const std::vector<Bench>& bench_entries() {
  static const std::vector<Bench> entries{
      {{"bench", ValueType::object, "", "", "the study whose figures are drawn (required)"},
       {},
       {},
       std::vector<Bench>{bench_quick(), bench_cases()}},
      {dir_info(BenchFiguresJob{}.dir),
       [](io::ObjectReader& r, BenchFiguresJob& b) {
         if (auto v = r.string("dir")) b.dir = *v;
       },
       [](const BenchFiguresJob& b, Json& j) { j["dir"] = b.dir.string(); }},
  };
  return entries;
}

template <class Doc>
Doc read_doc(const std::vector<Entry<Doc>>& entries, const nlohmann::json& j,
             const std::filesystem::path& file) {
  Doc d;
  d.file = file;
  io::ObjectReader r(j, file.string());
  read_entries(entries, r, d);
  r.finish();
  return d;
}

template <class Doc>
std::vector<KeyInfo> keys_of(const std::vector<Entry<Doc>>& entries) {
  std::vector<KeyInfo> keys;
  list_keys(entries, "", keys);
  return keys;
}

}  // namespace

LoadedJob load_job_file(const std::filesystem::path& path) {
  const auto j = io::read_json_file(path);
  LoadedJob loaded;
  if (j.contains("bench"))
    loaded.bench = read_doc(bench_entries(), j, path);
  else if (j.contains("jobs"))
    loaded.gallery = read_doc(gallery_entries(), j, path);
  else
    loaded.single = read_single(j, path);
  return loaded;
}

std::vector<KeyInfo> gallery_job_keys() { return keys_of(gallery_entries()); }
std::vector<KeyInfo> bench_job_keys() { return keys_of(bench_entries()); }

}  // namespace epviz::job
