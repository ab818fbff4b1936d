#pragma once
// The render thread's work: the only code that creates, drives and destroys
// sessions, so a session (and the GL context behind it) is only ever touched
// from one thread. It serves every connection in turn, one frame each per
// pass, and sleeps in the RenderHub whenever no connection can use a frame.
#include <cstdint>
#include <fstream>
#include <memory>
#include <vector>

#include "serve/image_encoder.hpp"
#include "serve/server.hpp"
#include "serve/session.hpp"
#include "serve/shared_state.hpp"

namespace epviz::serve {

class RenderLoop {
 public:
  RenderLoop(const ServerOptions& options, RenderHub& hub, SessionFactory make_session,
             const ServerLog& log, ServerCounters& counters);
  ~RenderLoop();
  RenderLoop(const RenderLoop&) = delete;
  RenderLoop& operator=(const RenderLoop&) = delete;

  // Serves until hub.request_stop(), then destroys every session (on this thread).
  void run();

 private:
  struct Client {
    std::shared_ptr<ConnectionLink> link;
    std::unique_ptr<Session> session;
    bool sized = false;          // no frame before the page has said how big its view is
    std::uint64_t last_seq = 0;  // of the last input event applied
    bool finished = false;       // remove (and destroy the session) after this pass
    bool recorded = false;       // its messages go to options.record_path
  };

  bool serve(Client& client);  // one pass for one connection; true when it rendered a frame
  void apply(Client& client, const ClientMessage& message);
  void send_frame(Client& client);
  void send(const Client& client, std::vector<std::uint8_t> message);
  void record(const Client& client, const std::string& line);

  const ServerOptions& options_;
  RenderHub& hub_;
  SessionFactory make_session_;
  const ServerLog& log_;
  ServerCounters& counters_;
  ImageEncoder encoder_;
  std::vector<Client> clients_;
  std::ofstream recording_;
  bool recording_taken_ = false;  // only the first connection is recorded
};

}  // namespace epviz::serve
