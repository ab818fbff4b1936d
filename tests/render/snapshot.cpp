#include "render/snapshot.hpp"

#include <cstdlib>
#include <sstream>

#include "check/frame_verdict.hpp"
#include "check/golden_files.hpp"
#include "io/png_reader.hpp"
#include "io/png_writer.hpp"

namespace epviz::testing {

SnapshotStore SnapshotStore::project() {
  SnapshotStore store;
  store.golden_dir = std::filesystem::path(EPVIZ_SOURCE_DIR) / "tests" / "snapshots";
  store.actual_dir = store.golden_dir / "actual";
  const char* update = std::getenv("EPVIZ_UPDATE_SNAPSHOTS");
  store.mode = (update != nullptr && std::string_view(update) == "1") ? SnapshotMode::update
                                                                      : SnapshotMode::compare;
  return store;
}

::testing::AssertionResult matches_snapshot(std::string_view name, int width, int height,
                                            std::span<const std::uint8_t> rgba,
                                            const SnapshotTolerance& tolerance,
                                            const SnapshotStore& store) {
  const auto golden = store.golden_dir / (std::string(name) + ".png");
  if (store.mode == SnapshotMode::update) {
    std::filesystem::create_directories(store.golden_dir);
    check::write_golden_png(golden, {width, height, rgba});
    return ::testing::AssertionSuccess() << "updated golden " << golden;
  }

  auto write_actual = [&](const std::vector<std::uint8_t>* diff) {
    std::filesystem::create_directories(store.actual_dir);
    const auto actual = store.actual_dir / (std::string(name) + ".png");
    io::write_png_rgba(actual, width, height, rgba);
    std::string where = "\n  actual: " + actual.string();
    if (diff != nullptr) {
      const auto diff_path = store.actual_dir / (std::string(name) + ".diff.png");
      io::write_png_rgba(diff_path, width, height, *diff);
      where += "\n  diff:   " + diff_path.string();
    }
    return where;
  };

  const auto expected = io::read_png_rgba(golden);
  if (!expected) {
    const std::string where = write_actual(nullptr);
    return ::testing::AssertionFailure()
           << "golden snapshot " << golden
           << " is missing or unreadable; a missing golden is a failure." << where
           << "\n  Review the actual image, then create the golden with EPVIZ_UPDATE_SNAPSHOTS=1.";
  }
  if (expected->width != width || expected->height != height) {
    const std::string where = write_actual(nullptr);
    return ::testing::AssertionFailure()
           << "snapshot '" << name << "' is " << width << "x" << height << " but the golden is "
           << expected->width << "x" << expected->height << where;
  }
  check::FrameJudge judge(tolerance.as_check_tolerance());
  const auto verdict =
      judge.judge({width, height, rgba}, {expected->width, expected->height, expected->rgba});
  if (verdict.passed) return ::testing::AssertionSuccess() << verdict.measure;
  const auto diff =
      check::diff_image(width, height, rgba, expected->rgba, tolerance.max_channel_difference);
  const std::string where = write_actual(&diff);
  std::ostringstream message;
  message << "snapshot '" << name << "' differs from " << golden << ": " << verdict.measure;
  message << " by more than " << tolerance.max_channel_difference << "/255 ("
          << verdict.pixels.pixels_differing << " pixels), largest channel difference "
          << verdict.pixels.largest_channel_difference << where;
  return ::testing::AssertionFailure() << message.str();
}

}  // namespace epviz::testing
