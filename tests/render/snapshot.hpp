#pragma once
// Image snapshot comparison for tests: an image is compared with a reviewed
// golden PNG under tests/snapshots/ with an explicit tolerance, the largest
// per-channel difference that still counts as equal and the fraction of
// pixels allowed to exceed it (Blender uses 4/255 and 1 %).
//
// - A missing golden is a FAILURE, never a silent new baseline.
// - The verdict is check::FrameJudge's, the one `epviz check` uses, and
//   goldens are written by check::write_golden_png, as `epviz check --update`
//   writes them.
// - On failure the actual image and a diff image go to tests/snapshots/actual/
//   (git-ignored): <name>.png and <name>.diff.png (check::diff_image:
//   over-threshold pixels red over a dimmed copy of the golden).
// - To create or update goldens, run the tests with EPVIZ_UPDATE_SNAPSHOTS=1:
//       EPVIZ_UPDATE_SNAPSHOTS=1 ./build/tests/test_render
//   then LOOK at every changed PNG before committing it.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "check/tolerance.hpp"

namespace epviz::testing {

// Wider than `epviz check`'s default: the same goldens serve both GL backends
// (EGL and OSMesa runs).
struct SnapshotTolerance {
  int max_channel_difference = 4;   // 0..255: a pixel differs if any channel differs by more
  double max_fraction_over = 0.01;  // of all pixels, how many may differ

  // The same, as the tolerance `epviz check` judges frames by.
  check::Tolerance as_check_tolerance() const {
    check::Tolerance t;
    t.metric = check::Metric::pixel;
    t.max_channel_difference = max_channel_difference;
    t.max_differing_percent = 100.0 * max_fraction_over;
    return t;
  }
};

enum class SnapshotMode { compare, update };

struct SnapshotStore {
  std::filesystem::path golden_dir;  // <source>/tests/snapshots
  std::filesystem::path actual_dir;  // <golden_dir>/actual
  SnapshotMode mode = SnapshotMode::compare;

  // The project's store; update mode when EPVIZ_UPDATE_SNAPSHOTS=1.
  static SnapshotStore project();
};

// Compares `rgba` (top-down RGBA8) with the golden <name>.png. In update mode
// writes the golden instead and succeeds.
::testing::AssertionResult matches_snapshot(std::string_view name, int width, int height,
                                            std::span<const std::uint8_t> rgba,
                                            const SnapshotTolerance& tolerance = {},
                                            const SnapshotStore& store = SnapshotStore::project());

}  // namespace epviz::testing
