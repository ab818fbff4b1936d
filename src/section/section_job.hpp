#pragma once
// The section file that `epviz section` reads (docs/sections.md): a case, the
// orbits' starts (a level of C1, C0 and a count, or explicit states), when to
// stop, the surface, the method and the CSV to write. Read strictly, as every
// job file: an unknown key, a wrong type or a value out of range is one line
// naming the file, the key and what is allowed (io::BadInput).
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/json_reader.hpp"
#include "io/output_paths.hpp"
#include "io/print_size.hpp"
#include "physics/body.hpp"
#include "physics/cases.hpp"
#include "physics/level_set.hpp"
#include "section/section_coords.hpp"
#include "sim/section.hpp"

namespace epviz::section {

// One method the orbits run with, at its setting: adaptive methods take
// `tol`, fixed-step ones `step`.
struct SectionMethod {
  sim::Method method = sim::Method::dop853;
  double tol = 1e-10;
  double step = 0.01;
};

// "dop853 tol 1e-10", "rk4 step 0.05": the method and the setting it uses,
// as the CSV's method column and the panels' titles name it.
std::string method_label(const SectionMethod& m);

inline constexpr std::size_t kMaxSectionMethods = 8;

// Which sheet of the surface the picture shows (docs/sections.md, "Sheets"):
// a surface gamma3 = 0 on a level is covered twice by the plotted
// coordinates (gamma1, Omega3), once for gamma2 > 0 and once for gamma2 < 0.
// "sheet": "gamma2 > 0" draws the crossings with gamma2 > 0 only;
// "sheets": "gamma2" draws both, each in a panel of its own. Crossings on
// the fold itself (the component exactly 0) are in neither. The CSV keeps
// every crossing.
struct SheetChoice {
  enum class Show { positive, negative, both_apart };
  sim::StateComponent component = sim::StateComponent::gamma2;
  Show show = Show::both_apart;
};

// "sheet" of `r`'s object ("C > 0" or "C < 0", C a state component neither
// the surface's function nor one of `coords`), and with `both_allowed` also
// "sheets" ("C": both sheets apart); nullopt when neither is given. Read
// wherever a sheet is chosen (a section file; a render job's "section").
std::optional<SheetChoice> read_sheet(io::ObjectReader& r, const sim::SectionSurface& surface,
                                      const PlotCoords& coords, bool both_allowed = true);

struct SectionJob {
  std::string file;  // for messages
  physics::Case case_id = physics::Case::kovalevskaya;
  physics::Body body;
  std::optional<physics::Level> level;  // with `orbits`, or else...
  int orbits = 0;
  std::vector<physics::InitialState> states;  // ...explicit starts
  int crossings = 200;                        // per orbit, at most
  double t_end = 1e4;                         // per orbit, at most
  sim::SectionSurface surface;
  // One method ("method", "tol", "step"), or several ("methods"), each
  // running every orbit: a panel each in the figure, side by side.
  std::vector<SectionMethod> methods{SectionMethod{}};
  double max_drift = 1e-6;  // relative drift of C1 or |gamma|^2 that loses an orbit
  // The plot's axes: two state components or Andoyer–Deprit variables
  // (default_section_coords).
  PlotCoords coords{sim::StateComponent::gamma1, sim::StateComponent::omega3};
  std::optional<SheetChoice> sheet;  // none: every crossing on one plane
  std::string csv;
  std::string png, svg, pdf;  // optional pictures of the crossings
  // The pictures' printed size: "figure_width", "font_size", "dpi" as given
  // ("" where not), checked when read. Kept as text so that a command's
  // --figure-width/--font-size/--dpi can replace each one (print_key_names).
  io::PrintSizeText print;
  std::string hash;  // of the file's parsed content: the shards of one section share it
};

// The keys a section surface and its plot are given by, wherever one is read
// (a section file; a render job's "section"), so that each has one name,
// default and check. Each reads its key of `r`'s object into `s`, left as it
// is when the key is absent; the caller finishes `r`.
void read_surface_function(io::ObjectReader& r, sim::SectionSurface& s);   // "function"
void read_surface_value(io::ObjectReader& r, sim::SectionSurface& s);      // "value"
void read_surface_direction(io::ObjectReader& r, sim::SectionSurface& s);  // "direction"
void read_surface(io::ObjectReader& r, sim::SectionSurface& s);            // all three
// The plot's axes where none are given (see SectionJob::coords).
std::array<sim::StateComponent, 2> default_coords(sim::StateComponent surface);
// "coords" of `r`'s object: two state components, default_coords(surface) when absent.
std::array<sim::StateComponent, 2> read_coords(io::ObjectReader& r, sim::StateComponent surface);
// A section file's surface and axes, which may also be Andoyer–Deprit
// variables (docs/sections.md, "Andoyer–Deprit variables"): "function" one
// of state_function_names() or "andoyer_l", "andoyer_g"; "coords" two of
// all_plot_coords(), by default (l, L/G) on a g surface, (g, G) on an l
// surface, else default_coords.
void read_section_function(io::ObjectReader& r, sim::SectionSurface& s);
PlotCoords default_section_coords(const sim::SectionSurface& s);
PlotCoords read_section_coords(io::ObjectReader& r, const sim::SectionSurface& s);
// For help: the state functions' names ("omega1" ... "gamma3") and the
// surface value's range ("-1e6 to 1e6").
inline constexpr double kSurfaceValueLimit = 1e6;
std::vector<std::string> state_function_names();
std::string surface_value_range();

// The keys of SectionJob::print as messages name them ("FILE: key 'dpi'").
io::PrintSizeText print_key_names(const SectionJob& job);

// Throws io::BadInput.
SectionJob read_section_job(const std::filesystem::path& file);
// The same from a JSON object already read, `name` naming it in messages (the
// file, or "epviz.section" for Python's dictionaries); without `needs_csv`
// "csv" may be left out (the crossings are returned, not written).
SectionJob read_section_object(const nlohmann::json& doc, const std::string& name,
                               bool needs_csv = true);

// Every output path given can be written, and none is the section file or
// another output (io/output_paths.hpp); throws io::BadInput naming the key.
// `csv_from`: what named the CSV when not the file's key "csv" ("--out");
// `more`: the command's other outputs (--h5).
void check_outputs(const SectionJob& job, const std::string& csv_from = "",
                   const io::NamedPaths& more = {});

// The orbits' initial states: the explicit ones, or those level_states builds
// on the level (gammas that carry none are skipped). Throws io::BadInput when
// there is none, naming the least energy of the level's C0, or when a state
// breaks the case's conditions (e.g. Goryachev–Chaplygin's C0 = 0).
std::vector<physics::InitialState> section_starts(const SectionJob& job);

// The section's runs are every method with every start, method by method:
// run r is method r / starts of start r % starts. A shard (`--shard I/N`)
// runs a contiguous range of them, so that its crossings are a contiguous
// slice of the CSV.
struct SectionRun {
  std::size_t method = 0;  // index into job.methods
  std::size_t start = 0;   // index into the starts; the orbit is start + 1
};
SectionRun section_run_of(long run, std::size_t starts);

}  // namespace epviz::section
