// Every shipped render job, at a gallery tile's size and at 720p, drawn as
// `epviz render` draws it (the system TTF): no text the painter puts over or
// beside the 3D view (the overlay window, the labels, the legend, the keys)
// covers a run's current point, at the first, the middle and the last frame.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "job/job_file.hpp"
#include "job/job_plan.hpp"
#include "job/shipped_jobs.hpp"
#include "paint/frame_drawer.hpp"
#include "paint/frame_painter.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;

struct Text {
  std::string what;
  paint::Box box;
};

std::vector<Text> texts_of(const paint::PaintedAnnotations& a) {
  std::vector<Text> out;
  if (a.overlay_window) out.push_back({"the overlay window", *a.overlay_window});
  if (a.marks_key) out.push_back({"the marks' key", *a.marks_key});
  for (const auto& l : a.labels) out.push_back({"label '" + l.text + "'", l.box});
  for (const auto& l : a.legend) out.push_back({"legend '" + l.text + "'", l.box});
  return out;
}

TEST(ShippedJobs, NoTextCoversARunsCurrentPoint) {
  const auto dir = job::shipped_jobs_dir();
  ASSERT_FALSE(dir.empty());
  int checked = 0;
  for (const auto& shipped : job::shipped_jobs(dir)) {
    const auto loaded = job::load_job_file(shipped.file);
    if (!loaded.single) continue;  // galleries are tiles of these; bench figures are charts
    for (const auto& [w, h] : {std::pair{640, 360}, {1280, 720}}) {
      auto job = *loaded.single;
      job.scene.width = w;
      job.scene.height = h;
      const auto plan = job::plan_job(job);
      paint::FrameDrawer drawer(plan, job.scene);
      paint::FramePainter painter(et::shared_gl_context(), w, h);
      for (const int frame : {0, plan.frames / 2, plan.frames - 1}) {
        drawer.draw(frame, painter);
        const auto& a = painter.annotations();
        std::vector<paint::Box> marks = a.ghosts;
        if (a.current_mark) marks.push_back(*a.current_mark);
        ASSERT_FALSE(marks.empty()) << shipped.name;
        // Every run of a comparison has its mark (unless behind the sphere's
        // projection, which the scenes' cameras never put them).
        for (const auto& t : texts_of(a))
          for (std::size_t m = 0; m < marks.size(); ++m)
            EXPECT_FALSE(t.box.intersects(marks[m]))
                << shipped.name << " at " << w << "x" << h << ", frame " << frame << ": " << t.what
                << " covers run " << (m + 1 == marks.size() ? 1 : m + 2) << "'s current point";
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 6 * 2 * 3);
}

}  // namespace
}  // namespace epviz
