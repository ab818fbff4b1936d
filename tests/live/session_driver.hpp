#pragma once
// Drives a LiveSession the way the page does: events in frame pixels, a frame
// rendered after each batch, controls found by the names the session reports
// (so the tests do not hard-code a layout).
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>

#include "live/live_session.hpp"
#include "physics/cases.hpp"
#include "render/gl_context.hpp"

namespace epviz::live::testing {

// A session that starts from case `c`'s preset.
inline SessionOptions starting_with(physics::Case c) {
  SessionOptions o;
  o.initial = preset_setup(c);
  return o;
}

inline render::GlContext& shared_gl() {
  static std::unique_ptr<render::GlContext> gl =
      render::make_gl_context(render::gl_backend_from_environment(), 64, 64);
  return *gl;
}

// A hash of the picture, to tell whether it changed.
inline std::uint64_t image_hash(const render::RgbaImage& image) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::uint8_t b : image.pixels) h = (h ^ b) * 1099511628211ull;
  return h;
}

class SessionDriver {
 public:
  // `builtin_font`: ImGui's bitmap font, pictures the same on every machine;
  // false: the system font `epviz render` uses, for comparing with a render.
  explicit SessionDriver(SessionOptions options, int width = 960, int height = 540,
                         bool builtin_font = true) {
    options.fixed_clock = true;
    options.builtin_font = builtin_font;
    session = std::make_unique<LiveSession>(shared_gl(), std::move(options));
    session->resize(width, height);
    settle();
  }

  // Renders frames until the session wants none (at most `max_frames`; a
  // playing scene always wants one); returns the hash of the last picture.
  std::uint64_t settle(int max_frames = 12) {
    for (int i = 0; i < max_frames && session->wants_frame(); ++i)
      last_hash = image_hash(session->render());
    return last_hash;
  }
  std::uint64_t frames(int n) {
    for (int i = 0; i < n; ++i) last_hash = image_hash(session->render());
    return last_hash;
  }

  Rect control(const std::string& name) const {
    const auto& c = session->panel().controls();
    const auto it = c.find(name);
    if (it == c.end()) {
      ADD_FAILURE() << "no control named '" << name << "' in the last frame";
      return {0, 0, 0, 0};
    }
    return it->second;
  }
  bool has_control(const std::string& name) const {
    return session->panel().controls().count(name) > 0;
  }

  void send(render::InputEvent e) { session->input(std::move(e)); }
  void move(float x, float y) {
    render::InputEvent e;
    e.kind = render::InputEvent::Kind::mouse_move;
    e.x = x, e.y = y;
    send(e);
  }
  void button(float x, float y, bool down, int b = 0) {
    render::InputEvent e;
    e.kind = render::InputEvent::Kind::mouse_button;
    e.x = x, e.y = y, e.button = b, e.down = down;
    send(e);
  }
  void click_at(float x, float y) {
    move(x, y);
    button(x, y, true);
    button(x, y, false);
    settle();
  }
  void click(const std::string& name) {
    const Rect r = control(name);
    click_at(r[0] + r[2] / 2, r[1] + r[3] / 2);
  }
  // A left-button drag from (x0, y0) by (dx, dy) in `steps` moves.
  void drag(float x0, float y0, float dx, float dy, int steps = 8) {
    move(x0, y0);
    button(x0, y0, true);
    for (int i = 1; i <= steps; ++i)
      move(x0 + dx * float(i) / float(steps), y0 + dy * float(i) / float(steps));
    button(x0 + dx, y0 + dy, false);
    settle(40);
  }
  void wheel(float x, float y, float notches) {
    render::InputEvent e;
    e.kind = render::InputEvent::Kind::wheel;
    e.x = x, e.y = y, e.wheel_y = notches;
    send(e);
    settle();
  }
  void key(const std::string& k, bool ctrl = false) {
    render::InputEvent e;
    e.kind = render::InputEvent::Kind::key;
    e.key = k, e.ctrl = ctrl, e.down = true;
    send(e);
    e.down = false;
    send(e);
  }
  void type(const std::string& text) {
    for (char c : text) {
      key(std::string(1, c));
      render::InputEvent t;
      t.kind = render::InputEvent::Kind::text;
      t.text = std::string(1, c);
      send(t);
    }
  }

  // Holds or releases Ctrl (a key event carries the modifiers ImGui sees).
  void ctrl(bool down) {
    render::InputEvent e;
    e.kind = render::InputEvent::Kind::key;
    e.key = "Control", e.ctrl = down, e.down = down;
    send(e);
  }
  // Types `text` into a slider or drag box the way ImGui lets a user type
  // any number (Ctrl+click, the text selected, then Enter); `at`: where
  // across the control to click (a box of three numbers: its first at 0.1).
  void type_into(const std::string& name, const std::string& text, float at = 0.5f) {
    const Rect r = control(name);
    const float x = r[0] + r[2] * at, y = r[1] + r[3] / 2;
    move(x, y);
    ctrl(true);
    button(x, y, true);
    button(x, y, false);
    ctrl(false);
    settle();
    type(text);
    key("Enter");
    settle();
  }

  std::unique_ptr<LiveSession> session;
  std::uint64_t last_hash = 0;
};

}  // namespace epviz::live::testing
