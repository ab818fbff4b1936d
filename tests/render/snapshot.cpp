#include "render/snapshot.hpp"

#include <stb/stb_image.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "io/png_writer.hpp"

namespace epviz::testing {
namespace {

struct LoadedPng {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

bool load_png(const std::filesystem::path& path, LoadedPng& out) {
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &out.width, &out.height, &channels, 4);
    if (data == nullptr) return false;
    out.rgba.assign(data, data + static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4);
    stbi_image_free(data);
    return true;
}

}  // namespace

SnapshotStore SnapshotStore::project() {
    SnapshotStore store;
    store.golden_dir = std::filesystem::path(EPVIZ_SOURCE_DIR) / "tests" / "snapshots";
    store.actual_dir = store.golden_dir / "actual";
    const char* update = std::getenv("EPVIZ_UPDATE_SNAPSHOTS");
    store.mode = (update != nullptr && std::string_view(update) == "1") ? SnapshotMode::update : SnapshotMode::compare;
    return store;
}

ImageDifference compare_images(int width, int height, std::span<const std::uint8_t> actual,
                               std::span<const std::uint8_t> expected, int max_channel_difference) {
    ImageDifference result;
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (actual.size() != pixels * 4 || expected.size() != pixels * 4) {
        result.same_size = false;
        return result;
    }
    result.diff_rgba.resize(pixels * 4);
    for (std::size_t p = 0; p < pixels; ++p) {
        int largest = 0;
        for (int c = 0; c < 4; ++c)
            largest = std::max(largest, std::abs(int(actual[p * 4 + c]) - int(expected[p * 4 + c])));
        result.largest_channel_difference = std::max(result.largest_channel_difference, largest);
        std::uint8_t* d = &result.diff_rgba[p * 4];
        if (largest > max_channel_difference) {
            ++result.pixels_over;
            // Bright red, stronger for larger differences, so small drifts still show.
            d[0] = static_cast<std::uint8_t>(std::min(255, 128 + largest));
            d[1] = 0;
            d[2] = 0;
        } else {
            // A faded grey copy of the actual image as context.
            const int grey = (actual[p * 4] + actual[p * 4 + 1] + actual[p * 4 + 2]) / 3;
            d[0] = d[1] = d[2] = static_cast<std::uint8_t>(grey / 4);
        }
        d[3] = 255;
    }
    result.fraction_over = pixels > 0 ? static_cast<double>(result.pixels_over) / static_cast<double>(pixels) : 0.0;
    return result;
}

::testing::AssertionResult matches_snapshot(std::string_view name, int width, int height,
                                            std::span<const std::uint8_t> rgba, const SnapshotTolerance& tolerance,
                                            const SnapshotStore& store) {
    const auto golden = store.golden_dir / (std::string(name) + ".png");
    if (store.mode == SnapshotMode::update) {
        std::filesystem::create_directories(store.golden_dir);
        io::write_png_rgba(golden, width, height, rgba, {.compression_level = 9, .filter = -1});
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

    LoadedPng expected;
    if (!load_png(golden, expected)) {
        const std::string where = write_actual(nullptr);
        return ::testing::AssertionFailure()
               << "golden snapshot " << golden << " is missing or unreadable; a missing golden is a failure."
               << where << "\n  Review the actual image, then create the golden with EPVIZ_UPDATE_SNAPSHOTS=1.";
    }
    if (expected.width != width || expected.height != height) {
        const std::string where = write_actual(nullptr);
        return ::testing::AssertionFailure() << "snapshot '" << name << "' is " << width << "x" << height
                                             << " but the golden is " << expected.width << "x" << expected.height
                                             << where;
    }
    const auto difference = compare_images(width, height, rgba, expected.rgba, tolerance.max_channel_difference);
    if (difference.fraction_over <= tolerance.max_fraction_over)
        return ::testing::AssertionSuccess() << difference.pixels_over << " pixels over " << tolerance.max_channel_difference;
    const std::string where = write_actual(&difference.diff_rgba);
    std::ostringstream message;
    message << "snapshot '" << name << "' differs from " << golden << ": " << difference.pixels_over << " pixels ("
            << 100.0 * difference.fraction_over << " %) differ by more than " << tolerance.max_channel_difference
            << " (allowed " << 100.0 * tolerance.max_fraction_over << " %), largest channel difference "
            << difference.largest_channel_difference << where;
    return ::testing::AssertionFailure() << message.str();
}

}  // namespace epviz::testing
