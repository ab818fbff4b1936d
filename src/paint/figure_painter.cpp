#include "paint/figure_painter.hpp"

#include "paint/chart_painter.hpp"
#include "paint/heat_map_painter.hpp"
#include "paint/table_painter.hpp"

namespace epviz::paint {

ChartFont chart_font(const render::ImGuiOverlay& overlay) {
  return {overlay.label_font_px(),
          [&overlay](const std::string& text) { return overlay.text_size(text).x; }};
}

render::RendererOptions renderer_options(const ChartOptions& options) {
  render::RendererOptions ro;
  ro.width = options.width;
  ro.height = options.height;
  ro.msaa_samples = options.msaa_samples;
  ro.overlay = true;
  ro.overlay_options.builtin_font = options.builtin_font;
  ro.overlay_options.font_size_px = chart_font_px(options);
  ro.overlay_options.light_style = true;
  return ro;
}

render::RgbaImage paint_drawing(render::GlContext& context, const ChartOptions& options,
                                const std::function<FigureDrawing(const ChartFont&)>& draw) {
  context.make_current();
  render::Renderer renderer(context, renderer_options(options));
  const FigureDrawing drawing = draw(chart_font(*renderer.overlay()));
  if (drawing.width != options.width || drawing.height != options.height)
    renderer.resize(drawing.width, drawing.height);
  renderer.begin_frame(kPaper);
  for (const auto& layer : drawing.layers)
    renderer.draw_2d(layer.list, layer.clip ? &*layer.clip : nullptr);
  return renderer.finish_frame();
}

render::RgbaImage paint_figure(render::GlContext& context, const Figure& figure,
                               const ChartOptions& options) {
  return paint_drawing(context, options,
                       [&](const ChartFont& font) { return draw_figure(figure, options, font); });
}

render::RgbaImage paint_chart(render::GlContext& context, const ChartSpec& spec,
                              const ChartOptions& options) {
  return paint_drawing(context, options,
                       [&](const ChartFont& font) { return draw_chart(spec, options, font); });
}

render::RgbaImage paint_heat_map(render::GlContext& context, const HeatMapSpec& spec,
                                 const ChartOptions& options) {
  return paint_drawing(context, options, [&](const ChartFont& font) {
    return draw_heat_map(spec, options, font, false);
  });
}

render::RgbaImage paint_heat_map_fitted(render::GlContext& context, const HeatMapSpec& spec,
                                        const ChartOptions& options) {
  return paint_drawing(context, options, [&](const ChartFont& font) {
    return draw_heat_map(spec, options, font, true);
  });
}

render::RgbaImage paint_table(render::GlContext& context, const TableSpec& spec,
                              const ChartOptions& options) {
  return paint_drawing(context, options,
                       [&](const ChartFont& font) { return draw_table(spec, options, font); });
}

}  // namespace epviz::paint
