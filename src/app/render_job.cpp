#include "app/render_job.hpp"

#include "app/usage_error.hpp"
#include "job/schema.hpp"

namespace epviz::app {
namespace {

// A single job: the schema's keys; the output name defaults to the frame
// prefix or, for a video, the job file's name.
RenderJob read_single(const nlohmann::json& j, const std::filesystem::path& file) {
  job::JobDocument d = job::read_job(j, file.string());
  RenderJob job;
  job.file = file;
  job.simulation = std::move(d.simulation);
  job.runs = std::move(d.runs);
  job.scene = std::move(d.scene);
  job.output = std::move(d.output);
  if (job.output.name.empty())
    job.output.name = job.output.format == OutputFormat::png ? "frame" : file.stem().string();
  return job;
}

}  // namespace

LoadedJob load_render_job(const std::filesystem::path& path) {
  LoadedJob loaded;
  try {
    const auto j = io::read_json_file(path);
    if (j.contains("bench")) {
      BenchFiguresJob b;
      b.file = path;
      io::ObjectReader r(j, path.string());
      if (auto bench = r.object("bench")) {
        if (auto q = bench->boolean("quick")) b.quick = *q;
        if (const auto* cases = bench->raw("cases")) {
          if (!cases->is_array()) bench->fail("cases", "expected an array of case names");
          for (const auto& c : *cases) {
            if (!c.is_string()) bench->fail("cases", "expected an array of case names");
            b.cases.push_back(c.get<std::string>());
          }
        }
        bench->finish();
      }
      if (auto v = r.string("dir")) b.dir = *v;
      r.finish();
      loaded.bench = std::move(b);
      return loaded;
    }
    if (!j.contains("jobs")) {
      loaded.single = read_single(j, path);
      return loaded;
    }
    GalleryJob g;
    g.file = path;
    io::ObjectReader r(j, path.string());
    const auto* list = r.raw("jobs");
    if (!list->is_array() || list->empty())
      r.fail("jobs", "expected a non-empty array of job file names");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const auto& item = (*list)[i];
      if (!item.is_string())
        r.fail("jobs", "item " + std::to_string(i) + ": expected a job file name");
      const auto sub = path.parent_path() / item.get<std::string>();
      g.jobs.push_back(read_single(io::read_json_file(sub), sub));
    }
    if (auto t = r.object("tile")) {
      if (auto v = t->integer("width", 16, 4096)) g.tile_width = int(*v);
      if (auto v = t->integer("height", 16, 4096)) g.tile_height = int(*v);
      if (auto v = t->integer("columns", 1, 16)) g.columns = int(*v);
      if (auto v = t->number("at")) {
        if (*v < 0 || *v > 1) t->fail("at", "expected a fraction of the run from 0 to 1");
        g.at = *v;
      }
      t->finish();
    }
    if (auto v = r.choice("videos", {"none", "mp4", "webm", "gif"}))
      g.videos = *v == "none" ? std::nullopt : output_format_from_name(*v);
    if (auto v = r.boolean("grid_video")) g.grid_video = *v;
    if (auto v = r.string("dir")) g.dir = *v;
    r.finish();
    loaded.gallery = std::move(g);
    return loaded;
  } catch (const io::JobError& e) {
    throw UsageError(e.what());
  }
}

}  // namespace epviz::app
