#pragma once
// What the frame server serves: one Session per connected browser tab, an
// application that takes input and produces pictures. The server knows
// nothing of what the pictures show (the epviz live scene implements this in
// src/live); it only moves events in and compressed frames out.
//
// Threading: a session is created, used and destroyed on the server's render
// thread only (the thread that owns the GL context), never concurrently.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "render/image.hpp"
#include "render/input_event.hpp"

namespace epviz::serve {

// A file the user asked for (a saved frame, a render job): sent to the
// browser, which offers it as a download.
struct Download {
  std::string name;  // file name only, no directories
  std::string mime;  // "image/png", "application/json"
  std::vector<std::uint8_t> bytes;
};

// How long the parts of the last render() took, as the session measured
// them (simulate: advancing the run; draw: issuing the picture; read back:
// copying it out of GL). Zero where a session does not tell; the server then
// counts all of render() as draw.
struct RenderStages {
  double simulate_ms = 0.0;
  double draw_ms = 0.0;
  double read_back_ms = 0.0;
};

class Session {
 public:
  virtual ~Session() = default;

  // The browser's view size in frame pixels (called before the first frame,
  // and whenever the page is resized). Sizes are already clamped by the server.
  virtual void resize(int width, int height) = 0;
  // The view is rendered at `scale` of the page's size (the pixel budget or
  // adaptive resolution; 1: full size), called before the resize that
  // applies it. A session whose interface has a fixed size in pixels scales
  // it by this, so that the page shows it the same size at every scale.
  virtual void set_view_scale(double scale) { (void)scale; }
  // One input event; positions are in the pixels of the frames this session renders.
  virtual void input(const render::InputEvent& event) = 0;
  // Whether the next frame could differ from the last one rendered: playing,
  // input arrived, resized, or nothing rendered yet. The server skips
  // rendering while this is false.
  virtual bool wants_frame() const = 0;
  // Renders the next frame (advancing the simulation when playing). The
  // image stays valid until the next call.
  virtual const render::RgbaImage& render() = 0;
  virtual RenderStages last_render_stages() const { return {}; }
  // Files and one-line messages for the user produced since the last call.
  virtual std::vector<Download> take_downloads() { return {}; }
  virtual std::vector<std::string> take_notices() { return {}; }
  // Where the main controls of the last rendered frame are, as a JSON object
  // of named rectangles in frame pixels ({"play": [x, y, w, h], ...}), or ""
  // for none: the server puts it in the frame header as "controls" so that
  // the page and browser tests can find a control without guessing a layout.
  virtual std::string controls_json() const { return {}; }
};

// Called on the render thread for each new connection.
using SessionFactory = std::function<std::unique_ptr<Session>()>;

}  // namespace epviz::serve
