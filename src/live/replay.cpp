#include "live/replay.hpp"

#include <string>
#include <variant>

#include "serve/protocol.hpp"

namespace epviz::live {

ReplayCounts replay(serve::Session& session, std::istream& recording) {
  ReplayCounts n;
  std::string line;
  for (long number = 1; std::getline(recording, line); ++number) {
    if (line.empty()) continue;
    if (line == R"({"type":"render"})") {
      session.render();
      ++n.frames;
      continue;
    }
    serve::ClientMessage message;
    try {
      message = serve::parse_client_message(line);
    } catch (const serve::ProtocolError& e) {
      throw std::runtime_error("recording line " + std::to_string(number) + ": " + e.what());
    }
    ++n.messages;
    if (const auto* r = std::get_if<serve::Resize>(&message))
      session.resize(r->width, r->height);
    else if (const auto* e = std::get_if<render::InputEvent>(&message))
      session.input(*e);
    // Acks only pace the server; they change nothing in a session.
  }
  return n;
}

}  // namespace epviz::live
