#include "app/render_job.hpp"

#include <array>
#include <cctype>
#include <cmath>

#include "app/usage_error.hpp"

namespace epviz::app {
namespace {

constexpr std::array<std::pair<OutputFormat, std::string_view>, 4> kFormats{{
    {OutputFormat::png, "png"}, {OutputFormat::mp4, "mp4"}, {OutputFormat::webm, "webm"}, {OutputFormat::gif, "gif"}}};

// "#rrggbb" or "#rrggbbaa".
scene::Rgba parse_colour(io::ObjectReader& r, const std::string& key, const std::string& text) {
  auto hex = [&](std::size_t i) {
    const std::string h = text.substr(i, 2);
    if (h.size() != 2 || !std::isxdigit(unsigned(h[0])) || !std::isxdigit(unsigned(h[1])))
      r.fail(key, "expected a colour \"#rrggbb\" or \"#rrggbbaa\", got \"" + text + "\"");
    return float(std::stoi(h, nullptr, 16)) / 255.0f;
  };
  if (text.empty() || text[0] != '#' || (text.size() != 7 && text.size() != 9))
    r.fail(key, "expected a colour \"#rrggbb\" or \"#rrggbbaa\", got \"" + text + "\"");
  return {hex(1), hex(3), hex(5), text.size() == 9 ? hex(7) : 1.0f};
}

void read_colours(io::ObjectReader r, scene::Colours& c) {
  for (auto [key, slot] : {std::pair{"background", &c.background}, std::pair{"body", &c.body},
                           std::pair{"sphere", &c.sphere}, std::pair{"marker", &c.marker}})
    if (auto s = r.string(key)) *slot = parse_colour(r, key, *s);
  r.finish();
}

void read_layers(io::ObjectReader r, scene::Layers& l) {
  if (auto v = r.boolean("body")) l.body = *v;
  if (auto v = r.boolean("sphere")) l.sphere = *v;
  if (auto v = r.boolean("riccati")) l.riccati = *v;
  if (auto v = r.boolean("overlay")) l.overlay = *v;
  r.finish();
  if (!l.body && !l.sphere && !l.riccati && !l.overlay) r.fail("body", "every layer is switched off: nothing to draw");
}

void read_camera(io::ObjectReader r, scene::CameraSettings& c) {
  if (auto v = r.number("azimuth")) c.azimuth_deg = *v;
  if (auto v = r.number("elevation")) {
    if (std::abs(*v) >= 90.0) r.fail("elevation", "expected degrees strictly between -90 and 90");
    c.elevation_deg = *v;
  }
  if (auto v = r.positive_number("distance")) {
    if (*v <= 1.2) r.fail("distance", "expected more than 1.2 sphere radii (the camera would be inside the sphere)");
    c.distance = *v;
  }
  r.finish();
}

// The simulation section: the simulate fields, with "tol": "auto" allowed.
SimulationFields read_simulation(io::ObjectReader r, scene::SceneSettings& scene) {
  bool auto_tol = false;
  SimulationFields f = read_simulation_fields(r, &auto_tol);
  // Without a "tol" the tolerance follows the resolution, as with "auto".
  scene.auto_tolerance = auto_tol || !f.tol;
  scene.formulation_given = f.formulation.value.has_value();
  r.finish();
  return f;
}

RenderJob read_single(const nlohmann::json& j, const std::filesystem::path& file) {
  RenderJob job;
  job.file = file;
  io::ObjectReader r(j, file.string());
  auto& s = job.scene;
  if (auto v = r.string("title")) s.title = *v;
  if (auto sim = r.object("simulation"))
    job.simulation = read_simulation(*sim, s);
  else
    r.fail("simulation", "missing: a render job needs a \"simulation\" object (at least {\"case\": ...})");
  if (auto v = r.choice("view", {"body", "space"})) s.view = *v == "space" ? scene::View::space : scene::View::body;
  if (auto c = r.object("camera")) read_camera(*c, s.camera);
  if (auto l = r.object("layers")) read_layers(*l, s.layers);
  if (auto c = r.object("colours")) read_colours(*c, s.colours);
  if (auto t = r.object("trail")) {
    if (auto v = t->positive_number("length")) s.trail_length = *v;
    t->finish();
  }
  if (auto p = r.object("plane")) {
    if (auto v = p->positive_number("extent")) s.plane_extent = float(*v);
    p->finish();
  }
  if (auto v = r.integer("width", 16, 8192)) s.width = int(*v);
  if (auto v = r.integer("height", 16, 8192)) s.height = int(*v);
  if (auto v = r.positive_number("fps")) {
    if (*v > 240) r.fail("fps", "expected at most 240 frames per second");
    s.fps = *v;
  }
  if (auto v = r.positive_number("duration")) s.duration = *v;
  if (s.fps * s.duration > 1e6) r.fail("duration", "fps x duration exceeds a million frames");
  if (auto o = r.object("output")) {
    if (auto v = o->string("dir")) job.output.dir = *v;
    std::vector<std::string> names;
    for (auto& [f, n] : kFormats) names.emplace_back(n);
    if (auto v = o->choice("format", names)) job.output.format = *output_format_from_name(*v);
    if (auto v = o->string("name")) {
      if (v->empty() || v->find('/') != std::string::npos) o->fail("name", "expected a file name without '/'");
      job.output.name = *v;
    }
    o->finish();
  }
  r.finish();
  if (job.output.name.empty())
    job.output.name = job.output.format == OutputFormat::png ? "frame" : file.stem().string();
  return job;
}

}  // namespace

std::string_view output_format_name(OutputFormat f) {
  for (auto& [k, n] : kFormats)
    if (k == f) return n;
  return "?";
}

std::optional<OutputFormat> output_format_from_name(std::string_view s) {
  for (auto& [k, n] : kFormats)
    if (n == s) return k;
  return std::nullopt;
}

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
    if (!list->is_array() || list->empty()) r.fail("jobs", "expected a non-empty array of job file names");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const auto& item = (*list)[i];
      if (!item.is_string()) r.fail("jobs", "item " + std::to_string(i) + ": expected a job file name");
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
    if (auto v = r.string("dir")) g.dir = *v;
    r.finish();
    loaded.gallery = std::move(g);
    return loaded;
  } catch (const io::JobError& e) {
    throw UsageError(e.what());
  }
}

}  // namespace epviz::app
