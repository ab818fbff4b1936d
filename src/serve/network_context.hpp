#pragma once
// What the network thread's objects (HTTP sessions, WebSocket connections)
// share. The plain members are touched only from handlers on the one network
// thread, which is what keeps them unguarded; the Server owns this and
// outlives every connection.
#include <functional>
#include <memory>
#include <optional>
#include <unordered_map>

#include "serve/origin_policy.hpp"
#include "serve/server.hpp"
#include "serve/shared_state.hpp"

namespace epviz::serve {

class WebSocketConnection;

struct NetworkContext {
  NetworkContext(const ServerOptions& server_options, const ServerLog& server_log,
                 ServerCounters& server_counters, RenderHub& render_hub)
      : options(server_options), log(server_log), counters(server_counters), hub(render_hub) {}

  const ServerOptions& options;
  const ServerLog& log;
  ServerCounters& counters;
  RenderHub& hub;

  std::optional<OriginPolicy> origins;  // set once the port is bound, before the first accept
  long next_id = 1;
  int websocket_clients = 0;  // upgraded or upgrading; max_clients bounds this
  bool stopping = false;      // no new connections; the last one to finish calls on_all_closed
  // Owns every WebSocket connection until it finishes: a connection whose
  // reading is paused has no operation pending, so no handler keeps it alive.
  std::unordered_map<long, std::shared_ptr<WebSocketConnection>> connections;
  std::function<void()> on_all_closed;
};

}  // namespace epviz::serve
