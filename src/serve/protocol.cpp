#include "serve/protocol.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include "io/printable.hpp"

namespace epviz::serve {

using nlohmann::json;

ProtocolError::ProtocolError(std::string field, const std::string& message)
    : std::runtime_error(message), field_(std::move(field)) {}

namespace {

// A value quoted in an error message, cut short on a character boundary and
// escaped: the message goes to a log line and a WebSocket close reason (at
// most 123 bytes of valid UTF-8).
std::string quote(const json& value) {
  return io::printable(value.dump(-1, ' ', false, json::error_handler_t::replace), 24);
}

// Reads the fields of one message; every error names the message type and the field.
class Fields {
 public:
  Fields(const json& object, std::string type) : object_(object), type_(std::move(type)) {}

  const json* find(const char* name) const {
    const auto it = object_.find(name);
    return it == object_.end() ? nullptr : &*it;
  }
  const json& require(const char* name) const {
    const json* value = find(name);
    if (!value) fail(name, "is missing");
    return *value;
  }

  std::int64_t integer(const char* name, std::int64_t lo, std::int64_t hi) const {
    return integer_value(name, require(name), lo, hi);
  }
  std::int64_t optional_integer(const char* name, std::int64_t lo, std::int64_t hi) const {
    const json* value = find(name);
    return value ? integer_value(name, *value, lo, hi) : 0;
  }

  float number(const char* name, double max_abs) const {
    const json& value = require(name);
    if (!value.is_number()) fail(name, "must be a number, got " + std::string(value.type_name()));
    const double v = value.get<double>();
    if (!std::isfinite(v) || std::abs(v) > max_abs)
      fail(name, "must be within +-" + quote(max_abs) + ", got " + quote(value));
    return static_cast<float>(v);
  }

  // An optional number in [0, max]; `absent` when the field is not there.
  double optional_nonnegative(const char* name, double max, double absent) const {
    const json* value = find(name);
    if (!value) return absent;
    if (!value->is_number()) fail(name, "must be a number, got " + std::string(value->type_name()));
    const double v = value->get<double>();
    if (!std::isfinite(v) || v < 0 || v > max)
      fail(name, "must be within 0.." + quote(max) + ", got " + quote(*value));
    return v;
  }

  bool boolean(const char* name) const { return boolean_value(name, require(name)); }
  bool optional_boolean(const char* name) const {
    const json* value = find(name);
    return value && boolean_value(name, *value);
  }

  std::string string(const char* name, std::size_t min_bytes, std::size_t max_bytes) const {
    const json& value = require(name);
    if (!value.is_string()) fail(name, "must be a string, got " + std::string(value.type_name()));
    std::string s = value.get<std::string>();
    if (s.size() < min_bytes || s.size() > max_bytes)
      fail(name, "must be " + std::to_string(min_bytes) + ".." + std::to_string(max_bytes) +
                     " bytes long, got " + std::to_string(s.size()));
    return s;
  }

  [[noreturn]] void fail(const char* name, const std::string& problem) const {
    throw ProtocolError(name, type_ + ": field \"" + name + "\" " + problem);
  }

 private:
  std::int64_t integer_value(const char* name, const json& value, std::int64_t lo,
                             std::int64_t hi) const {
    // 3.0 is a float to nlohmann; a page that sends it has a bug worth hearing about.
    if (!value.is_number_integer())
      fail(name, "must be an integer, got " + std::string(value.type_name()) + " " + quote(value));
    const bool too_big =
        value.is_number_unsigned() && value.get<std::uint64_t>() > static_cast<std::uint64_t>(hi);
    if (too_big || value.get<std::int64_t>() < lo || value.get<std::int64_t>() > hi)
      fail(name,
           "must be " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " + quote(value));
    return value.get<std::int64_t>();
  }
  bool boolean_value(const char* name, const json& value) const {
    if (!value.is_boolean())
      fail(name, "must be true or false, got " + std::string(value.type_name()));
    return value.get<bool>();
  }

  const json& object_;
  std::string type_;
};

constexpr std::int64_t max_int = std::numeric_limits<std::int64_t>::max();

render::InputEvent pointer_event(const Fields& f, render::InputEvent::Kind kind) {
  render::InputEvent e;
  e.kind = kind;
  e.x = f.number("x", max_abs_position);
  e.y = f.number("y", max_abs_position);
  return e;
}

ClientMessage parse_object(const json& message) {
  const auto type_it = message.find("type");
  if (type_it == message.end()) throw ProtocolError("type", "message: field \"type\" is missing");
  if (!type_it->is_string())
    throw ProtocolError("type", "message: field \"type\" must be a string, got " +
                                    std::string(type_it->type_name()));
  const std::string type = type_it->get<std::string>();
  const Fields f(message, type);
  using Kind = render::InputEvent::Kind;

  if (type == "resize") {
    return Resize{static_cast<int>(f.integer("width", 1, max_view_pixels)),
                  static_cast<int>(f.integer("height", 1, max_view_pixels))};
  }
  if (type == "ack")
    return Ack{f.integer("frame", 0, max_int),
               f.optional_nonnegative("decode_ms", max_decode_ms, -1.0)};

  render::InputEvent e;
  if (type == "move") {
    e = pointer_event(f, Kind::mouse_move);
  } else if (type == "button") {
    e = pointer_event(f, Kind::mouse_button);
    e.button = static_cast<int>(f.integer("button", 0, 2));
    e.down = f.boolean("down");
  } else if (type == "wheel") {
    e = pointer_event(f, Kind::wheel);
    e.wheel_x = f.number("dx", max_abs_wheel);
    e.wheel_y = f.number("dy", max_abs_wheel);
  } else if (type == "key") {
    e.kind = Kind::key;
    e.key = f.string("key", 1, max_key_bytes);
    e.down = f.boolean("down");
    e.ctrl = f.optional_boolean("ctrl");
    e.shift = f.optional_boolean("shift");
    e.alt = f.optional_boolean("alt");
    e.super = f.optional_boolean("meta");
  } else if (type == "text") {
    e.kind = Kind::text;
    e.text = f.string("text", 0, max_text_bytes);
  } else if (type == "focus") {
    e.kind = Kind::focus;
    e.down = f.boolean("focused");
  } else {
    throw ProtocolError("type", "message: unknown \"type\" " + quote(*type_it));
  }
  e.seq = static_cast<std::uint64_t>(f.optional_integer("seq", 0, max_int));
  return e;
}

// The header as JSON text; strings a session made up (notices, file names)
// may hold invalid UTF-8, which is replaced rather than thrown on.
std::string dump(const json& header) {
  return header.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace

std::string encode_client_message(const ClientMessage& message) {
  using Kind = render::InputEvent::Kind;
  json j;
  if (const auto* r = std::get_if<Resize>(&message)) {
    j = {{"type", "resize"}, {"width", r->width}, {"height", r->height}};
  } else if (const auto* a = std::get_if<Ack>(&message)) {
    j = {{"type", "ack"}, {"frame", a->frame}};
    if (a->decode_ms >= 0) j["decode_ms"] = a->decode_ms;
  } else {
    const auto& e = std::get<render::InputEvent>(message);
    switch (e.kind) {
      case Kind::mouse_move: j = {{"type", "move"}, {"x", e.x}, {"y", e.y}}; break;
      case Kind::mouse_button:
        j = {{"type", "button"}, {"x", e.x}, {"y", e.y}, {"button", e.button}, {"down", e.down}};
        break;
      case Kind::wheel:
        j = {{"type", "wheel"}, {"x", e.x}, {"y", e.y}, {"dx", e.wheel_x}, {"dy", e.wheel_y}};
        break;
      case Kind::key:
        j = {{"type", "key"},    {"key", e.key}, {"down", e.down}, {"ctrl", e.ctrl},
             {"shift", e.shift}, {"alt", e.alt}, {"meta", e.super}};
        break;
      case Kind::text: j = {{"type", "text"}, {"text", e.text}}; break;
      case Kind::focus: j = {{"type", "focus"}, {"focused", e.down}}; break;
    }
    if (e.seq != 0) j["seq"] = e.seq;
  }
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

ClientMessage parse_client_message(std::string_view text) {
  json message = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (message.is_discarded()) throw ProtocolError("", "message is not valid JSON");
  if (!message.is_object())
    throw ProtocolError("",
                        "message must be a JSON object, got " + std::string(message.type_name()));
  return parse_object(message);
}

std::vector<std::uint8_t> encode_server_message(const json& header,
                                                std::span<const std::uint8_t> payload) {
  const std::string text = dump(header);
  const auto n = static_cast<std::uint32_t>(text.size());
  std::vector<std::uint8_t> bytes;
  bytes.reserve(4 + text.size() + payload.size());
  for (int shift = 0; shift < 32; shift += 8)
    bytes.push_back(static_cast<std::uint8_t>(n >> shift));
  bytes.insert(bytes.end(), text.begin(), text.end());
  bytes.insert(bytes.end(), payload.begin(), payload.end());
  return bytes;
}

std::vector<std::uint8_t> encode_frame_message(const FrameInfo& info,
                                               std::span<const std::uint8_t> image) {
  json header = {{"kind", "frame"},
                 {"frame", info.frame},
                 {"seq", info.seq},
                 {"width", info.width},
                 {"height", info.height},
                 {"mime", info.mime},
                 {"render_ms", info.render_ms},
                 {"simulate_ms", info.stages.simulate_ms},
                 {"draw_ms", info.stages.draw_ms},
                 {"read_back_ms", info.stages.read_back_ms},
                 {"encode_ms", info.encode_ms}};
  if (info.written_frame > 0)
    header["written"] = {
        {"frame", info.written_frame}, {"queue_ms", info.queue_ms}, {"send_ms", info.send_ms}};
  if (const FrameInfo::Adaptive& a = info.adaptive; a.budget_ms > 0) {
    header["adaptive"] = {{"budget_ms", a.budget_ms},
                          {"detail", a.detail},
                          {"resting", a.resting},
                          {"server_ms", a.server_ms}};
    if (a.page_decode_ms >= 0) header["adaptive"]["page_decode_ms"] = a.page_decode_ms;
  }
  // A session's own JSON: parsed so that a malformed one is dropped, not sent.
  if (!info.controls_json.empty()) {
    json controls = json::parse(info.controls_json, nullptr, /*allow_exceptions=*/false);
    if (controls.is_object()) header["controls"] = std::move(controls);
  }
  return encode_server_message(header, image);
}

std::vector<std::uint8_t> encode_file_message(const Download& download) {
  std::string name = download.name;
  if (const auto slash = name.find_last_of("/\\"); slash != std::string::npos)
    name.erase(0, slash + 1);
  return encode_server_message({{"kind", "file"}, {"name", name}, {"mime", download.mime}},
                               download.bytes);
}

std::vector<std::uint8_t> encode_notice_message(std::string_view text) {
  return encode_server_message({{"kind", "notice"}, {"text", std::string(text)}});
}

ServerMessage decode_server_message(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < 4)
    throw ProtocolError("", "server message shorter than its 4-byte header length");
  std::uint32_t n = 0;
  for (int i = 3; i >= 0; --i) n = (n << 8) | bytes[static_cast<std::size_t>(i)];
  if (n > bytes.size() - 4)
    throw ProtocolError(
        "", "server message header length " + std::to_string(n) + " exceeds the message");
  const auto header_bytes = bytes.subspan(4, n);
  ServerMessage message;
  message.header = json::parse(header_bytes.begin(), header_bytes.end(), nullptr, false);
  if (!message.header.is_object())
    throw ProtocolError("", "server message header is not a JSON object");
  message.payload.assign(bytes.begin() + 4 + n, bytes.end());
  return message;
}

}  // namespace epviz::serve
