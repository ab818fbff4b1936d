#pragma once
// A frame of a scene as a vector figure (`epviz render --format svg|pdf`):
// one page of the frame's pixel size in the PNG's layout (paint::layout_for),
// the 3D view (body, sphere, trails) an embedded raster that the GL painter
// draws at the frame's resolution, and everything 2D over it and beside it
// as vectors: the marks and labels over the 3D view, the Riccati plane's
// panel, the separation chart, the legend, the caption and the overlay
// window with its text. In a PDF the text is text (selectable, searchable).
//
//   paint::FrameDrawer drawer(plan, settings);
//   vector::write_frame_stills(drawer, painter, {119, 119}, {"out", "frame", FigureFormat::pdf}, {});
#include <filesystem>
#include <string>

#include "io/frame_range.hpp"
#include "io/progress.hpp"
#include "paint/frame_drawer.hpp"
#include "paint/frame_files.hpp"
#include "paint/frame_painter.hpp"
#include "scene/frame.hpp"
#include "vector/figure_format.hpp"

namespace epviz::vector {

// The file's bytes; `format` must be svg or pdf (png throws
// std::invalid_argument). The painter's size is the page's in units of
// `pt_per_unit` points (a figure at a printed size: 72 / dpi, the 3D view
// embedded at dpi).
std::string frame_still_bytes(paint::FramePainter& painter, const scene::Frame& frame,
                              FigureFormat format, double pt_per_unit = 1.0);

// Where the stills go: dir/<name>_<frame>.svg or .pdf, numbered as the PNG frames are.
struct StillFiles {
  std::filesystem::path dir;
  std::string name;
  FigureFormat format = FigureFormat::pdf;
  double pt_per_unit = 1.0;  // frame_still_bytes
};

// Frames range.first..range.last into `files`, each written atomically (the
// frames before the range are integrated through, not drawn). A numerical
// failure ends the frames early and is returned in the result.
paint::FramesWritten write_frame_stills(paint::FrameDrawer& drawer, paint::FramePainter& painter,
                                        const io::FrameRange& range, const StillFiles& files,
                                        const io::ProgressOptions& progress);

}  // namespace epviz::vector
