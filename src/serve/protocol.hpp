#pragma once
// The wire format of docs/serve.md as plain functions: page → server JSON
// parsed into data (no I/O here, so every malformed case is unit-testable),
// and server → page binary messages built from data.
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/input_event.hpp"
#include "serve/session.hpp"

namespace epviz::serve {

// `resize`: the page's view in frame pixels (not yet clamped to the server's limits).
struct Resize {
  int width = 0;
  int height = 0;
};

// `ack`: the page has shown frame `frame`, which took it `decode_ms` to
// decode (optional; negative when not sent). The server weighs the page's
// decoding with its own drawing when it sizes frames (adaptive resolution):
// on some machines decoding, not drawing, is what limits the frame rate.
struct Ack {
  std::int64_t frame = 0;
  double decode_ms = -1.0;
};

using ClientMessage = std::variant<render::InputEvent, Resize, Ack>;

// A page message the server refuses. `field()` names the offending field
// ("type", "width", ...), or is empty when the message as a whole is wrong
// (not JSON, not an object); what() is one line that also names it.
class ProtocolError : public std::runtime_error {
 public:
  ProtocolError(std::string field, const std::string& message);
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

// Bounds that make a message malformed rather than merely large. The server
// clamps sizes further (ServerOptions::max_width); these only reject values
// no real page sends, so a bug or an attacker is told so instead of being
// silently clamped.
inline constexpr int max_view_pixels = 16384;      // resize width/height: 1 .. this
inline constexpr double max_abs_position = 1.0e6;  // x, y (may be negative: drags leave the view)
inline constexpr double max_abs_wheel = 1.0e4;     // dx, dy in notches
inline constexpr std::size_t max_text_bytes = 64;  // `text`
inline constexpr std::size_t max_key_bytes = 32;   // `key` (longest DOM key names are ~20)
inline constexpr double max_decode_ms = 60000.0;   // ack `decode_ms`: 0 .. this

// Parses one page → server text message; throws ProtocolError.
ClientMessage parse_client_message(std::string_view text);
// The inverse: the message as the page would send it (recordings are written
// with it and read back with parse_client_message).
std::string encode_client_message(const ClientMessage& message);

// Server → page: `[u32 LE header length][header JSON][payload]`.
std::vector<std::uint8_t> encode_server_message(const nlohmann::json& header,
                                                std::span<const std::uint8_t> payload = {});

struct FrameInfo {
  std::int64_t frame = 0;  // 1, 2, ... per connection
  std::uint64_t seq = 0;   // last input seq applied before rendering, 0 if none
  int width = 0;
  int height = 0;
  std::string mime;        // "image/jpeg" or "image/png"
  double render_ms = 0.0;  // the session's render(): simulate + draw + read back
  RenderStages stages;     // render_ms split as the session measured it
  double encode_ms = 0.0;
  // The queue and send times of the newest earlier frame whose write had
  // completed (`written_frame`, 0: none yet); this frame's are not known
  // when its header is written.
  std::int64_t written_frame = 0;
  double queue_ms = 0.0;
  double send_ms = 0.0;
  std::string controls_json;  // the session's named control rectangles (a JSON object), or ""
  // Adaptive resolution's choice, sent when it is on (budget_ms > 0): the
  // share of each side drawn while the picture moves, and the measured costs
  // it was chosen from (the server's render + encode, the page's decoding of
  // a frame of that size; negative: not reported yet).
  struct Adaptive {
    double budget_ms = 0.0;
    double detail = 1.0;
    bool resting = false;  // this frame is the full-size one drawn at rest
    double server_ms = 0.0;
    double page_decode_ms = -1.0;
  } adaptive;
};
std::vector<std::uint8_t> encode_frame_message(const FrameInfo& info,
                                               std::span<const std::uint8_t> image);
// Directories in download.name are dropped: the page only needs a file name.
std::vector<std::uint8_t> encode_file_message(const Download& download);
std::vector<std::uint8_t> encode_notice_message(std::string_view text);

// The inverse of encode_server_message, for tests and tools; throws
// ProtocolError for a truncated message or a header that is not a JSON object.
struct ServerMessage {
  nlohmann::json header;
  std::vector<std::uint8_t> payload;
};
ServerMessage decode_server_message(std::span<const std::uint8_t> bytes);

}  // namespace epviz::serve
