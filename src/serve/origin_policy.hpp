#pragma once
// Which pages may drive this server. A browser lets any web page open a
// WebSocket to 127.0.0.1, and a name the attacker controls can be made to
// resolve to 127.0.0.1 (DNS rebinding), so every request must name this
// server in its Host header, and an upgrade must come from this server's own
// page (its Origin) or from an origin the user allowed with --allow-origin.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace epviz::serve {

class OriginPolicy {
 public:
  // `bind` as given to the server (an address or a name), `port` the bound
  // port; `allowed` are extra origins ("http://host:port"), matched exactly
  // after lowering case and dropping a default port.
  OriginPolicy(std::string bind, unsigned short port, const std::vector<std::string>& allowed);

  // Why a Host header does not name this server, or nullopt when it does.
  // A server bound to a wildcard address (0.0.0.0, ::) cannot know its
  // names: it accepts address literals and localhost, never other names.
  std::optional<std::string> host_problem(std::string_view host) const;
  // Why an upgrade's Origin header is refused, or nullopt. `present` false:
  // no Origin header, which browsers always send, so the request is not
  // from a web page (a script or a test client) and is accepted. `host` is
  // the request's Host (already accepted): behind a wildcard address the
  // page must come from the very host it connects to.
  std::optional<std::string> origin_problem(bool present, std::string_view origin,
                                            std::string_view host) const;

  // "http://host:port" lowered with the default port dropped, or nullopt when
  // `origin` is not of that form (a path, user info, another scheme...).
  static std::optional<std::string> normalize_origin(std::string_view origin);

 private:
  struct Authority {
    std::string host;  // lowered; IPv6 without brackets
    unsigned short port = 0;
  };
  static std::optional<Authority> parse_authority(std::string_view text, unsigned short fallback);
  static std::optional<std::pair<std::string, Authority>> split_origin(std::string_view origin);
  bool names_this_server(const Authority& a) const;

  std::string bind_;  // lowered; IPv6 without brackets
  unsigned short port_;
  bool loopback_;
  bool wildcard_;
  std::vector<std::string> allowed_;  // normalized
  std::vector<Authority> allowed_hosts_;
};

}  // namespace epviz::serve
