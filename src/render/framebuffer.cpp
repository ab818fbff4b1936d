#include "render/framebuffer.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace epviz::render {
namespace {

thread_local double read_back_ms = 0.0;

void check_complete(const char* which) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string("offscreen framebuffer (") + which +
                             ") incomplete, status 0x" + std::to_string(status));
}

}  // namespace

OffscreenFramebuffer::OffscreenFramebuffer(int width, int height, int samples)
    : width_(width), height_(height) {
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = samples <= 1 ? 0 : std::min(samples, static_cast<int>(max_samples));
  create();
}

OffscreenFramebuffer::~OffscreenFramebuffer() { destroy(); }

void OffscreenFramebuffer::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  destroy();
  width_ = width;
  height_ = height;
  create();
}

void OffscreenFramebuffer::create() {
  if (width_ <= 0 || height_ <= 0)
    throw std::invalid_argument("framebuffer size must be positive, got " + std::to_string(width_) +
                                "x" + std::to_string(height_));
  // The single-sample target: what we read pixels from.
  glGenFramebuffers(1, &resolve_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
  glGenRenderbuffers(1, &resolve_colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, resolve_colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_colour_);

  if (samples_ > 1) {
    glGenFramebuffers(1, &draw_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
    glGenRenderbuffers(1, &draw_colour_);
    glBindRenderbuffer(GL_RENDERBUFFER, draw_colour_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width_, height_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, draw_colour_);
  } else {
    draw_fbo_ = resolve_fbo_;  // draw straight into the readback target
  }
  glGenRenderbuffers(1, &draw_depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, draw_depth_);
  if (samples_ > 1)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width_,
                                     height_);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, draw_depth_);
  check_complete(samples_ > 1 ? "multisampled" : "single-sample");
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
  check_complete("resolve");
  check_gl_error("creating the offscreen framebuffer");
}

void OffscreenFramebuffer::destroy() {
  if (draw_fbo_ != 0 && draw_fbo_ != resolve_fbo_) glDeleteFramebuffers(1, &draw_fbo_);
  if (resolve_fbo_ != 0) glDeleteFramebuffers(1, &resolve_fbo_);
  if (draw_colour_ != 0) glDeleteRenderbuffers(1, &draw_colour_);
  if (draw_depth_ != 0) glDeleteRenderbuffers(1, &draw_depth_);
  if (resolve_colour_ != 0) glDeleteRenderbuffers(1, &resolve_colour_);
  draw_fbo_ = resolve_fbo_ = draw_colour_ = draw_depth_ = resolve_colour_ = 0;
}

void OffscreenFramebuffer::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
  glViewport(0, 0, width_, height_);
}

void OffscreenFramebuffer::resolve() const {
  if (draw_fbo_ == resolve_fbo_) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
}

RgbaImage OffscreenFramebuffer::read_pixels_rgba() const {
  RgbaImage image;
  read_pixels_rgba(image);
  return image;
}

double last_read_back_ms() { return read_back_ms; }

void OffscreenFramebuffer::read_pixels_rgba(RgbaImage& image) const {
  resolve();
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  image.width = width_;
  image.height = height_;
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  image.pixels.resize(row * static_cast<std::size_t>(height_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
  check_gl_error("reading back the frame");
  // GL's row 0 is the bottom one; images and video want the top row first.
  std::vector<std::uint8_t> swap(row);
  for (int y = 0; y < height_ / 2; ++y) {
    std::uint8_t* top = image.pixels.data() + static_cast<std::size_t>(y) * row;
    std::uint8_t* bottom = image.pixels.data() + static_cast<std::size_t>(height_ - 1 - y) * row;
    std::memcpy(swap.data(), top, row);
    std::memcpy(top, bottom, row);
    std::memcpy(bottom, swap.data(), row);
  }
  read_back_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace epviz::render
