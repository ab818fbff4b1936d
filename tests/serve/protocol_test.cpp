// The wire format (docs/serve.md) without any network: every page message
// parses to the right data, every kind of malformed message is refused with
// an error naming what was wrong, and server messages have the documented layout.
#include <gtest/gtest.h>

#include <string>

#include "serve/protocol.hpp"

namespace epviz::serve {
namespace {

using Kind = render::InputEvent::Kind;

render::InputEvent event_of(const std::string& text) {
  ClientMessage message = parse_client_message(text);
  const auto* event = std::get_if<render::InputEvent>(&message);
  if (!event) throw std::runtime_error("not an input event: " + text);
  return *event;
}

TEST(ServeProtocol, ParsesResize) {
  const ClientMessage m = parse_client_message(R"({"type":"resize","width":1280,"height":720})");
  ASSERT_TRUE(std::holds_alternative<Resize>(m));
  EXPECT_EQ(std::get<Resize>(m).width, 1280);
  EXPECT_EQ(std::get<Resize>(m).height, 720);
}

TEST(ServeProtocol, ParsesAck) {
  const ClientMessage m = parse_client_message(R"({"type":"ack","frame":42})");
  ASSERT_TRUE(std::holds_alternative<Ack>(m));
  EXPECT_EQ(std::get<Ack>(m).frame, 42);
  EXPECT_LT(std::get<Ack>(m).decode_ms, 0) << "no decoding time sent";
}

TEST(ServeProtocol, AckMayCarryThePagesDecodingTime) {
  const ClientMessage m = parse_client_message(R"({"type":"ack","frame":7,"decode_ms":12.25})");
  ASSERT_TRUE(std::holds_alternative<Ack>(m));
  EXPECT_EQ(std::get<Ack>(m).frame, 7);
  EXPECT_DOUBLE_EQ(std::get<Ack>(m).decode_ms, 12.25);
  EXPECT_DOUBLE_EQ(
      std::get<Ack>(parse_client_message(R"({"type":"ack","frame":7,"decode_ms":0})")).decode_ms,
      0.0);
}

TEST(ServeProtocol, ParsesMoveWithSeq) {
  const auto e = event_of(R"({"type":"move","x":12.5,"y":-3,"seq":9})");
  EXPECT_EQ(e.kind, Kind::mouse_move);
  EXPECT_FLOAT_EQ(e.x, 12.5f);
  EXPECT_FLOAT_EQ(e.y, -3.0f);
  EXPECT_EQ(e.seq, 9u);
}

TEST(ServeProtocol, SeqIsOptional) {
  EXPECT_EQ(event_of(R"({"type":"move","x":1,"y":2})").seq, 0u);
}

TEST(ServeProtocol, ParsesButton) {
  const auto e = event_of(R"({"type":"button","x":4,"y":5,"button":1,"down":true})");
  EXPECT_EQ(e.kind, Kind::mouse_button);
  EXPECT_FLOAT_EQ(e.x, 4.0f);
  EXPECT_FLOAT_EQ(e.y, 5.0f);
  EXPECT_EQ(e.button, 1);
  EXPECT_TRUE(e.down);
}

TEST(ServeProtocol, ParsesWheel) {
  const auto e = event_of(R"({"type":"wheel","x":1,"y":2,"dx":-0.5,"dy":3})");
  EXPECT_EQ(e.kind, Kind::wheel);
  EXPECT_FLOAT_EQ(e.wheel_x, -0.5f);
  EXPECT_FLOAT_EQ(e.wheel_y, 3.0f);
}

TEST(ServeProtocol, ParsesKeyWithModifiers) {
  const auto e =
      event_of(R"({"type":"key","key":"ArrowLeft","down":false,"ctrl":true,"meta":true})");
  EXPECT_EQ(e.kind, Kind::key);
  EXPECT_EQ(e.key, "ArrowLeft");
  EXPECT_FALSE(e.down);
  EXPECT_TRUE(e.ctrl);
  EXPECT_FALSE(e.shift);
  EXPECT_FALSE(e.alt);
  EXPECT_TRUE(e.super);  // DOM "meta" is ImGui's "super"
}

TEST(ServeProtocol, ParsesText) {
  const auto e = event_of(R"({"type":"text","text":"h\u00e9"})");
  EXPECT_EQ(e.kind, Kind::text);
  EXPECT_EQ(e.text, "h\xc3\xa9");
}

TEST(ServeProtocol, ParsesFocus) {
  const auto e = event_of(R"({"type":"focus","focused":true})");
  EXPECT_EQ(e.kind, Kind::focus);
  EXPECT_TRUE(e.down);
}

TEST(ServeProtocol, IgnoresUnknownFields) {
  EXPECT_NO_THROW(parse_client_message(R"({"type":"move","x":1,"y":2,"pressure":0.5})"));
}

// The error for `text`: its field() and a what() that names it.
struct Refusal {
  std::string field;
  std::string message;
};
Refusal refusal_of(const std::string& text) {
  try {
    parse_client_message(text);
  } catch (const ProtocolError& e) {
    return {e.field(), e.what()};
  }
  throw std::runtime_error("accepted: " + text);
}

void expect_refused(const std::string& text, const std::string& field,
                    const std::string& says = "") {
  SCOPED_TRACE(text);
  const Refusal r = refusal_of(text);
  EXPECT_EQ(r.field, field);
  if (!field.empty()) {
    EXPECT_NE(r.message.find("\"" + field + "\""), std::string::npos) << r.message;
  }
  if (!says.empty()) {
    EXPECT_NE(r.message.find(says), std::string::npos) << r.message;
  }
}

TEST(ServeProtocol, RefusesWhatIsNotJson) {
  expect_refused("{", "", "not valid JSON");
  expect_refused("hello", "", "not valid JSON");
  expect_refused("", "", "not valid JSON");
  expect_refused(R"({"type":"move","x":1e999,"y":0})", "", "not valid JSON");  // overflows a double
}

TEST(ServeProtocol, RefusesWhatIsNotAnObject) {
  expect_refused("[1,2]", "", "JSON object, got array");
  expect_refused("42", "", "got number");
  expect_refused(R"("resize")", "", "got string");
}

TEST(ServeProtocol, RefusesMissingOrUnknownType) {
  expect_refused(R"({"width":3})", "type", "missing");
  expect_refused(R"({"type":7})", "type", "must be a string");
  expect_refused(R"({"type":"warp"})", "type", "unknown");
}

TEST(ServeProtocol, RefusesMissingFields) {
  expect_refused(R"({"type":"resize","width":3})", "height", "missing");
  expect_refused(R"({"type":"ack"})", "frame", "missing");
  expect_refused(R"({"type":"move","x":1})", "y", "missing");
  expect_refused(R"({"type":"button","x":1,"y":2,"button":0})", "down", "missing");
  expect_refused(R"({"type":"wheel","x":1,"y":2,"dx":0})", "dy", "missing");
  expect_refused(R"({"type":"key","down":true})", "key", "missing");
  expect_refused(R"({"type":"text"})", "text", "missing");
  expect_refused(R"({"type":"focus"})", "focused", "missing");
}

TEST(ServeProtocol, RefusesWrongTypes) {
  expect_refused(R"({"type":"resize","width":"640","height":480})", "width", "integer");
  expect_refused(R"({"type":"resize","width":640.0,"height":480})", "width", "integer");
  expect_refused(R"({"type":"move","x":"1","y":2})", "x", "number");
  expect_refused(R"({"type":"button","x":1,"y":2,"button":1.5,"down":true})", "button", "integer");
  expect_refused(R"({"type":"button","x":1,"y":2,"button":0,"down":1})", "down", "true or false");
  expect_refused(R"({"type":"key","key":"a","down":true,"shift":"yes"})", "shift", "true or false");
  expect_refused(R"({"type":"text","text":["a"]})", "text", "string");
  expect_refused(R"({"type":"move","x":1,"y":2,"seq":"7"})", "seq", "integer");
  expect_refused(R"({"type":"ack","frame":null})", "frame", "integer");
}

TEST(ServeProtocol, RefusesOutOfRangeValues) {
  expect_refused(R"({"type":"resize","width":-640,"height":480})", "width", "1..16384");
  expect_refused(R"({"type":"resize","width":640,"height":0})", "height", "1..16384");
  expect_refused(R"({"type":"resize","width":100000,"height":480})", "width", "1..16384");
  expect_refused(R"({"type":"resize","width":18446744073709551615,"height":480})", "width");
  expect_refused(R"({"type":"ack","frame":-1})", "frame");
  expect_refused(R"({"type":"ack","frame":1,"decode_ms":-0.5})", "decode_ms", "0..");
  expect_refused(R"({"type":"ack","frame":1,"decode_ms":1e9})", "decode_ms", "0..");
  expect_refused(R"({"type":"ack","frame":1,"decode_ms":"3"})", "decode_ms", "number");
  expect_refused(R"({"type":"move","x":1,"y":2,"seq":-5})", "seq");
  expect_refused(R"({"type":"move","x":1e7,"y":2})", "x");
  expect_refused(R"({"type":"button","x":1,"y":2,"button":3,"down":true})", "button", "0..2");
  expect_refused(R"({"type":"wheel","x":1,"y":2,"dx":0,"dy":-1e9})", "dy");
}

// Whether `s` is well-formed UTF-8 (a WebSocket close reason must be).
bool is_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80         ? 1
                          : (c >> 5) == 6  ? 2
                          : (c >> 4) == 14 ? 3
                          : (c >> 3) == 30 ? 4
                                           : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
    i += n;
  }
  return true;
}

TEST(ServeProtocol, QuotedValuesAreShortValidUtf8OnOneLine) {
  std::string accents;
  for (int i = 0; i < 200; ++i) accents += "\u00e9";  // é, two bytes in UTF-8
  const Refusal r = refusal_of(R"({"type":"x)" + accents + "\"}");
  EXPECT_EQ(r.field, "type");
  EXPECT_TRUE(is_utf8(r.message)) << r.message;
  EXPECT_LE(r.message.size(), 123u) << r.message;  // the longest close reason
  const Refusal lines = refusal_of(R"({"type":"resize","width":"a\nb\u2028c","height":1})");
  EXPECT_EQ(lines.message.find('\n'), std::string::npos) << lines.message;
  EXPECT_EQ(lines.message.find("\u2028"), std::string::npos) << lines.message;
}

TEST(ServeProtocol, RefusesOverlongText) {
  EXPECT_NO_THROW(parse_client_message(R"({"type":"text","text":")" +
                                       std::string(max_text_bytes, 'a') + "\"}"));
  expect_refused(R"({"type":"text","text":")" + std::string(max_text_bytes + 1, 'a') + "\"}",
                 "text", "bytes");
  expect_refused(
      R"({"type":"key","key":")" + std::string(max_key_bytes + 1, 'k') + R"(","down":true})",
      "key");
  expect_refused(R"({"type":"key","key":"","down":true})", "key");
}

TEST(ServeProtocol, FrameMessageHasTheDocumentedLayout) {
  FrameInfo info;
  info.frame = 3;
  info.seq = 17;
  info.width = 640;
  info.height = 360;
  info.mime = "image/jpeg";
  info.render_ms = 1.5;
  info.stages = {0.25, 1.0, 0.125};
  info.encode_ms = 2.25;
  info.written_frame = 2;
  info.queue_ms = 0.5;
  info.send_ms = 0.75;
  const std::vector<std::uint8_t> image = {0xff, 0xd8, 0x00, 0x01};
  const auto bytes = encode_frame_message(info, image);

  const std::uint32_t n =
      bytes[0] | (bytes[1] << 8) | (bytes[2] << 16) | (static_cast<std::uint32_t>(bytes[3]) << 24);
  ASSERT_EQ(bytes.size(), 4 + n + image.size());
  const auto header = nlohmann::json::parse(bytes.begin() + 4, bytes.begin() + 4 + n);
  EXPECT_EQ(header["kind"], "frame");
  EXPECT_EQ(header["frame"], 3);
  EXPECT_EQ(header["seq"], 17);
  EXPECT_EQ(header["width"], 640);
  EXPECT_EQ(header["height"], 360);
  EXPECT_EQ(header["mime"], "image/jpeg");
  EXPECT_DOUBLE_EQ(header["render_ms"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(header["simulate_ms"].get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(header["draw_ms"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(header["read_back_ms"].get<double>(), 0.125);
  EXPECT_DOUBLE_EQ(header["encode_ms"].get<double>(), 2.25);
  EXPECT_EQ(header["written"]["frame"], 2);
  EXPECT_DOUBLE_EQ(header["written"]["queue_ms"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(header["written"]["send_ms"].get<double>(), 0.75);
  EXPECT_TRUE(std::equal(image.begin(), image.end(), bytes.begin() + 4 + n));

  const ServerMessage decoded = decode_server_message(bytes);
  EXPECT_EQ(decoded.header, header);
  EXPECT_EQ(decoded.payload, image);
}

TEST(ServeProtocol, FrameHeaderSaysWhatAdaptiveResolutionChoseAndFromWhat) {
  FrameInfo info;
  info.frame = 9;
  info.width = 800;
  info.height = 450;
  info.mime = "image/jpeg";
  EXPECT_FALSE(decode_server_message(encode_frame_message(info, {})).header.contains("adaptive"))
      << "adaptive resolution off: nothing to say";
  info.adaptive = {18.0, 0.625, false, 11.5, -1.0};
  auto header = decode_server_message(encode_frame_message(info, {})).header;
  ASSERT_TRUE(header.contains("adaptive"));
  EXPECT_DOUBLE_EQ(header["adaptive"]["budget_ms"].get<double>(), 18.0);
  EXPECT_DOUBLE_EQ(header["adaptive"]["detail"].get<double>(), 0.625);
  EXPECT_EQ(header["adaptive"]["resting"], false);
  EXPECT_DOUBLE_EQ(header["adaptive"]["server_ms"].get<double>(), 11.5);
  EXPECT_FALSE(header["adaptive"].contains("page_decode_ms")) << "the page has reported none";
  info.adaptive.page_decode_ms = 6.25;
  header = decode_server_message(encode_frame_message(info, {})).header;
  EXPECT_DOUBLE_EQ(header["adaptive"]["page_decode_ms"].get<double>(), 6.25);
}

TEST(ServeProtocol, FrameMessageBeforeAnyWriteHasNoWrittenTimes) {
  FrameInfo info;
  info.frame = 1;
  info.width = info.height = 16;
  info.mime = "image/png";
  const auto header = decode_server_message(encode_frame_message(info, {})).header;
  EXPECT_FALSE(header.contains("written"));
}

TEST(ServeProtocol, ClientMessagesSurviveEncodeAndParse) {
  // Recordings are written with encode_client_message and read back with parse_client_message.
  const std::vector<std::string> pages = {
      R"({"type":"resize","width":640,"height":480})",
      R"({"type":"ack","frame":12})",
      R"({"type":"ack","frame":13,"decode_ms":4.5})",
      R"({"type":"move","x":1.5,"y":-2,"seq":3})",
      R"({"type":"button","x":4,"y":5,"button":2,"down":true})",
      R"({"type":"wheel","x":1,"y":2,"dx":0.25,"dy":-1})",
      R"({"type":"key","key":"Enter","down":false,"ctrl":true,"shift":false,"alt":true,"meta":true})",
      R"({"type":"text","text":"h\u00e9"})",
      R"({"type":"focus","focused":false})",
  };
  for (const std::string& page : pages) {
    SCOPED_TRACE(page);
    const ClientMessage parsed = parse_client_message(page);
    const std::string encoded = encode_client_message(parsed);
    EXPECT_EQ(nlohmann::json::parse(encoded), nlohmann::json::parse(page)) << encoded;
    EXPECT_EQ(encode_client_message(parse_client_message(encoded)), encoded);
  }
}

TEST(ServeProtocol, FrameHeaderCarriesTheSessionsControls) {
  FrameInfo info;
  info.controls_json = R"({"play":[1,2,30,40]})";
  EXPECT_EQ(decode_server_message(encode_frame_message(info, {})).header["controls"]["play"],
            nlohmann::json::array({1, 2, 30, 40}));
  info.controls_json = "{broken";  // dropped, not sent
  EXPECT_FALSE(decode_server_message(encode_frame_message(info, {})).header.contains("controls"));
  info.controls_json = "";
  EXPECT_FALSE(decode_server_message(encode_frame_message(info, {})).header.contains("controls"));
}

TEST(ServeProtocol, FileMessageKeepsOnlyTheFileName) {
  const Download download{"../renders/frame 0001.png", "image/png", {1, 2, 3}};
  const ServerMessage m = decode_server_message(encode_file_message(download));
  EXPECT_EQ(m.header["kind"], "file");
  EXPECT_EQ(m.header["name"], "frame 0001.png");
  EXPECT_EQ(m.header["mime"], "image/png");
  EXPECT_EQ(m.payload, download.bytes);
}

TEST(ServeProtocol, NoticeMessageHasNoPayload) {
  const ServerMessage m =
      decode_server_message(encode_notice_message("saved \xff frame"));  // invalid UTF-8 survives
  EXPECT_EQ(m.header["kind"], "notice");
  EXPECT_NE(m.header["text"].get<std::string>().find("saved"), std::string::npos);
  EXPECT_TRUE(m.payload.empty());
}

TEST(ServeProtocol, DecodeRefusesTruncatedMessages) {
  EXPECT_THROW(decode_server_message(std::vector<std::uint8_t>{1, 0}), ProtocolError);
  EXPECT_THROW(decode_server_message(std::vector<std::uint8_t>{9, 0, 0, 0, '{', '}'}),
               ProtocolError);
  EXPECT_THROW(decode_server_message(std::vector<std::uint8_t>{2, 0, 0, 0, '[', ']'}),
               ProtocolError);
}

}  // namespace
}  // namespace epviz::serve
