#include "render/renderer.hpp"

#include <algorithm>
#include <numeric>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "render/gpu_mesh.hpp"

namespace epviz::render {
namespace {

void create_stream_buffer(GLuint& vao, GLuint& vertices, GLuint* indices) {
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vertices);
  glBindBuffer(GL_ARRAY_BUFFER, vertices);
  if (indices != nullptr) {
    glGenBuffers(1, indices);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, *indices);
  }
}

// Float attribute `index` of `size` components at float offset `offset` in vertices of `stride` floats.
void float_attribute(GLuint index, int size, int stride, int offset) {
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(
      index, size, GL_FLOAT, GL_FALSE, stride * static_cast<GLsizei>(sizeof(float)),
      reinterpret_cast<const void*>(static_cast<std::size_t>(offset) * sizeof(float)));
}

void delete_stream_buffer(GLuint vao, GLuint vertices, GLuint indices) {
  glDeleteVertexArrays(1, &vao);
  glDeleteBuffers(1, &vertices);
  if (indices != 0) glDeleteBuffers(1, &indices);
}

void standard_blending() {
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  // Colour blends "over"; alpha accumulates coverage so an opaque background stays opaque.
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

void push_colour(std::vector<float>& out, const glm::vec4& c) {
  out.insert(out.end(), {c.r, c.g, c.b, c.a});
}

}  // namespace

Renderer::Renderer(GlContext& context, const RendererOptions& options)
    : context_(context),
      // The context must be current before the first GL object is made.
      framebuffer_((context.make_current(), options.width), options.height, options.msaa_samples),
      mesh_program_(ShaderProgram::from_files("mesh.vert", "mesh.frag")),
      line_program_(ShaderProgram::from_files("line.vert", "line.frag", "line.geom")),
      marker_program_(ShaderProgram::from_files("marker.vert", "marker.frag", "marker.geom")),
      solid_program_(ShaderProgram::from_files("solid.vert", "solid.frag")) {
  // Lines: position, colour, width (8 floats), drawn as GL_LINES_ADJACENCY through an index list.
  create_stream_buffer(lines_.vao, lines_.vertices, &lines_.indices);
  float_attribute(0, 3, 8, 0);
  float_attribute(1, 4, 8, 3);
  float_attribute(2, 1, 8, 7);
  // Markers: position, fill, outline, (radius, outline width) (13 floats), one GL_POINT each.
  create_stream_buffer(markers_.vao, markers_.vertices, nullptr);
  float_attribute(0, 3, 13, 0);
  float_attribute(1, 4, 13, 3);
  float_attribute(2, 4, 13, 7);
  float_attribute(3, 2, 13, 11);
  // Filled triangles: position, colour (7 floats).
  create_stream_buffer(triangles_.vao, triangles_.vertices, nullptr);
  float_attribute(0, 3, 7, 0);
  float_attribute(1, 4, 7, 3);
  // Dots: the same, one GL_POINT each.
  create_stream_buffer(dots_.vao, dots_.vertices, nullptr);
  float_attribute(0, 3, 7, 0);
  float_attribute(1, 4, 7, 3);
  glBindVertexArray(0);
  if (options.overlay) overlay_ = std::make_unique<ImGuiOverlay>(options.overlay_options);
  check_gl_error("creating the renderer");
}

Renderer::~Renderer() {
  overlay_.reset();
  delete_stream_buffer(lines_.vao, lines_.vertices, lines_.indices);
  delete_stream_buffer(markers_.vao, markers_.vertices, 0);
  delete_stream_buffer(triangles_.vao, triangles_.vertices, 0);
  delete_stream_buffer(dots_.vao, dots_.vertices, 0);
}

void Renderer::resize(int width, int height) { framebuffer_.resize(width, height); }

void Renderer::begin_frame(const glm::vec4& background) {
  framebuffer_.bind_for_drawing();
  glDisable(GL_SCISSOR_TEST);
  glDepthMask(GL_TRUE);
  glClearColor(background.r, background.g, background.b, background.a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  labels_.clear();
  label_pixels_.clear();
  overlay_drawn_ = false;
}

void Renderer::set_gl_viewport(const Viewport& viewport) const {
  // Our viewports count rows from the top; GL counts them from the bottom.
  glViewport(viewport.x, framebuffer_.height() - viewport.y - viewport.height, viewport.width,
             viewport.height);
}

void Renderer::draw_meshes(const DrawList& list, const Camera& camera, const Lighting& lighting,
                           bool translucent) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < list.meshes().size(); ++i)
    if ((list.meshes()[i].material.colour.a < 1.0f) == translucent) order.push_back(i);
  if (order.empty()) return;
  if (translucent) {
    // Far to near by the depth of each mesh's origin in view space.
    auto depth = [&](std::size_t i) { return (camera.view * list.meshes()[i].model)[3].z; };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return depth(a) < depth(b); });
  }

  mesh_program_.use();
  mesh_program_.set("u_projection", camera.projection);
  mesh_program_.set("u_key_direction", glm::normalize(lighting.key_direction));
  mesh_program_.set("u_key_colour", lighting.key_colour);
  mesh_program_.set("u_fill_direction", glm::normalize(lighting.fill_direction));
  mesh_program_.set("u_fill_colour", lighting.fill_colour);
  mesh_program_.set("u_sky_colour", lighting.sky_colour);
  mesh_program_.set("u_ground_colour", lighting.ground_colour);
  glEnable(GL_CULL_FACE);
  if (translucent) {
    standard_blending();
    glDepthMask(GL_FALSE);
    // Pushed back a little: a line lying on the surface (a trail on the
    // sphere) must win the depth test against the surface it lies on.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 4.0f);
  } else {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
  for (std::size_t i : order) {
    const auto& item = list.meshes()[i];
    const glm::mat4 model_view = camera.view * item.model;
    mesh_program_.set("u_model_view", model_view);
    mesh_program_.set("u_normal_matrix", glm::transpose(glm::inverse(glm::mat3(model_view))));
    mesh_program_.set("u_colour", item.material.colour);
    mesh_program_.set("u_specular", item.material.specular);
    mesh_program_.set("u_shininess", item.material.shininess);
    mesh_program_.set("u_rim", item.material.rim);
    mesh_program_.set("u_lit", item.material.lit ? 1 : 0);
    if (translucent && item.material.back_faces) {
      // A convex shell drawn inside first, then outside, blends in the right order.
      glCullFace(GL_FRONT);
      item.mesh->draw();
      glCullFace(GL_BACK);
    }
    item.mesh->draw();
  }
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
}

void Renderer::draw_triangles(const DrawList& list, const glm::mat4& view_projection) {
  if (list.triangles().empty()) return;
  scratch_vertices_.clear();
  for (const auto& v : list.triangles()) {
    scratch_vertices_.insert(scratch_vertices_.end(), {v.position.x, v.position.y, v.position.z});
    push_colour(scratch_vertices_, v.colour);
  }
  standard_blending();
  solid_program_.use();
  solid_program_.set("u_view_projection", view_projection);
  glBindVertexArray(triangles_.vao);
  glBindBuffer(GL_ARRAY_BUFFER, triangles_.vertices);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(scratch_vertices_.size() * sizeof(float)),
               scratch_vertices_.data(), GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(list.triangles().size()));
}

void Renderer::draw_dots(const DrawList& list, const glm::mat4& view_projection) {
  if (list.dots().empty()) return;
  scratch_vertices_.clear();
  scratch_vertices_.reserve(7 * list.dot_vertices().size());
  for (const auto& v : list.dot_vertices()) {
    scratch_vertices_.insert(scratch_vertices_.end(), {v.position.x, v.position.y, v.position.z});
    push_colour(scratch_vertices_, v.colour);
  }
  standard_blending();
  solid_program_.use();
  solid_program_.set("u_view_projection", view_projection);
  glBindVertexArray(dots_.vao);
  glBindBuffer(GL_ARRAY_BUFFER, dots_.vertices);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(scratch_vertices_.size() * sizeof(float)),
               scratch_vertices_.data(), GL_STREAM_DRAW);
  // The point size set here (GL_PROGRAM_POINT_SIZE is off): a square of that many pixels.
  for (const auto& range : list.dots()) {
    glPointSize(range.size_px);
    glDrawArrays(GL_POINTS, static_cast<GLint>(range.first), static_cast<GLsizei>(range.count));
  }
  glPointSize(1.0f);
}

void Renderer::draw_lines(const DrawList& list, const glm::mat4& view_projection,
                          const glm::vec2& viewport_size) {
  if (list.polylines().empty()) return;
  const auto& vertices = list.line_vertices();
  scratch_vertices_.clear();
  scratch_indices_.clear();
  std::vector<std::uint32_t> strip;
  for (const auto& range : list.polylines()) {
    // A polyline whose every vertex is below the alpha threshold draws no
    // fragment (the shader discards them): skip it rather than expand it.
    bool visible = false;
    for (std::size_t i = 0; i < range.count && !visible; ++i)
      visible = vertices[range.first + i].colour.a >= min_alpha_;
    if (!visible) continue;
    const auto base = static_cast<std::uint32_t>(scratch_vertices_.size() / 8);
    // Drop repeated points: a zero-length segment has no direction to mitre with.
    strip.clear();
    for (std::size_t i = 0; i < range.count; ++i) {
      const auto& v = vertices[range.first + i];
      if (!strip.empty() && vertices[range.first + strip.back()].position == v.position) continue;
      strip.push_back(static_cast<std::uint32_t>(i));
    }
    bool closed = range.closed;
    // A polyline that ends where it starts is a loop: mitre the seam too.
    if (strip.size() > 2 && vertices[range.first + strip.front()].position ==
                                vertices[range.first + strip.back()].position) {
      strip.pop_back();
      closed = true;
    }
    const std::size_t n = strip.size();
    if (n < 2) continue;
    for (auto i : strip) {
      const auto& v = vertices[range.first + i];
      scratch_vertices_.insert(scratch_vertices_.end(), {v.position.x, v.position.y, v.position.z});
      push_colour(scratch_vertices_, v.colour);
      scratch_vertices_.push_back(range.width_px);
    }
    const std::size_t segments = closed ? n : n - 1;
    for (std::size_t s = 0; s < segments; ++s) {
      const std::size_t a = s, b = (s + 1) % n;
      // At an open end the neighbour is the end point itself: the shader then cuts square.
      const std::size_t prev = closed ? (s + n - 1) % n : (s == 0 ? a : s - 1);
      const std::size_t next = closed ? (s + 2) % n : (s + 2 < n ? s + 2 : b);
      for (std::size_t k : {prev, a, b, next})
        scratch_indices_.push_back(base + static_cast<std::uint32_t>(k));
    }
  }
  if (scratch_indices_.empty()) return;
  begin_screen_space_pass(line_program_, lines_, view_projection, viewport_size);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, lines_.indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(scratch_indices_.size() * sizeof(std::uint32_t)),
               scratch_indices_.data(), GL_STREAM_DRAW);
  glDrawElements(GL_LINES_ADJACENCY, static_cast<GLsizei>(scratch_indices_.size()), GL_UNSIGNED_INT,
                 nullptr);
}

void Renderer::begin_screen_space_pass(ShaderProgram& program, const StreamBuffer& buffer,
                                       const glm::mat4& view_projection,
                                       const glm::vec2& viewport_size) {
  standard_blending();
  program.use();
  program.set("u_view_projection", view_projection);
  program.set("u_viewport_size", viewport_size);
  program.set("u_min_alpha", min_alpha_);
  glBindVertexArray(buffer.vao);
  glBindBuffer(GL_ARRAY_BUFFER, buffer.vertices);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(scratch_vertices_.size() * sizeof(float)),
               scratch_vertices_.data(), GL_STREAM_DRAW);
}

void Renderer::draw_markers(const DrawList& list, const glm::mat4& view_projection,
                            const glm::vec2& viewport_size) {
  if (list.markers().empty()) return;
  scratch_vertices_.clear();
  for (const auto& m : list.markers()) {
    scratch_vertices_.insert(scratch_vertices_.end(), {m.position.x, m.position.y, m.position.z});
    push_colour(scratch_vertices_, m.fill);
    push_colour(scratch_vertices_, m.outline);
    scratch_vertices_.insert(scratch_vertices_.end(), {m.radius_px, m.outline_px});
  }
  begin_screen_space_pass(marker_program_, markers_, view_projection, viewport_size);
  // A large scatter in batches, each finished before the next: llvmpipe
  // keeps a call's geometry-shader output until the frame is read, some
  // 500 bytes a marker (a scatter of a million: 830 MB, in batches 360 MB).
  constexpr std::size_t kBatch = 1 << 16;
  const std::size_t n = list.markers().size();
  for (std::size_t first = 0; first < n; first += kBatch) {
    if (first > 0) glFinish();
    glDrawArrays(GL_POINTS, static_cast<GLint>(first),
                 static_cast<GLsizei>(std::min(kBatch, n - first)));
  }
}

void Renderer::queue_label(const TextLabel& label, const glm::vec2& pixel) {
  labels_.push_back(label);
  label_pixels_.push_back(pixel);
}

void Renderer::draw_3d(const DrawList& list, const Camera& camera, const Viewport& viewport,
                       const Lighting& lighting) {
  framebuffer_.bind_for_drawing();
  set_gl_viewport(viewport);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  const glm::mat4 view_projection = camera.view_projection();
  const glm::vec2 size(static_cast<float>(viewport.width), static_cast<float>(viewport.height));

  draw_meshes(list, camera, lighting, false);
  draw_triangles(list, view_projection);
  draw_dots(list, view_projection);
  // Lines and markers test depth against the opaque meshes but do not write
  // it while they draw: lines lying on one surface (a trail crossing a grid)
  // would otherwise hide each other at random where their depths tie.
  glDepthMask(GL_FALSE);
  draw_lines(list, view_projection, size);
  draw_markers(list, view_projection, size);
  // Then their depth alone, so that a translucent shell drawn next tints what
  // lies behind it but not the lines and markers in front of it. Faint lines
  // (alpha < 0.5, such as a grid on the shell) leave no depth: they read as
  // part of the surface and take its tint, instead of cutting dark gaps in it.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_TRUE);
  min_alpha_ = 0.5f;
  draw_lines(list, view_projection, size);
  draw_markers(list, view_projection, size);
  min_alpha_ = 0.01f;
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  draw_meshes(list, camera, lighting, true);

  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
  for (const auto& label : list.labels())
    if (auto pixel = project_to_pixel(camera, viewport, label.position))
      queue_label(label, glm::vec2(*pixel));
  // Hand the view to the rasteriser now: llvmpipe draws nothing before a
  // flush, so its threads would otherwise wait idle while the caller builds
  // the 2D panels and the overlay on one core.
  glFlush();
  check_gl_error("drawing a 3D view");
}

void Renderer::draw_2d(const DrawList& list, const Viewport* clip) {
  framebuffer_.bind_for_drawing();
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  if (clip != nullptr) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(clip->x, framebuffer_.height() - clip->y - clip->height, clip->width, clip->height);
  }
  const glm::mat4 view_projection = Camera::pixel_space(width(), height()).view_projection();
  const glm::vec2 size(static_cast<float>(width()), static_cast<float>(height()));
  draw_triangles(list, view_projection);
  draw_dots(list, view_projection);
  draw_lines(list, view_projection, size);
  draw_markers(list, view_projection, size);
  glDisable(GL_SCISSOR_TEST);
  glDepthMask(GL_TRUE);
  glBindVertexArray(0);
  for (const auto& label : list.labels()) queue_label(label, glm::vec2(label.position));
  check_gl_error("drawing a 2D list");
}

void Renderer::draw_overlay(const std::function<void()>& build_ui) {
  if (!overlay_) return;
  framebuffer_.bind_for_drawing();
  std::vector<PlacedLabel> placed;
  placed.reserve(labels_.size());
  for (std::size_t i = 0; i < labels_.size(); ++i)
    placed.push_back({label_pixels_[i], &labels_[i]});
  overlay_->draw_frame(width(), height(), build_ui, placed);
  overlay_drawn_ = true;
  check_gl_error("drawing the ImGui overlay");
}

RgbaImage Renderer::finish_frame() {
  RgbaImage image;
  finish_frame(image);
  return image;
}

void Renderer::finish_frame(RgbaImage& image) {
  if (!overlay_drawn_ && !labels_.empty()) draw_overlay();
  framebuffer_.read_pixels_rgba(image);
}

}  // namespace epviz::render
