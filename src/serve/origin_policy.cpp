#include "serve/origin_policy.hpp"

#include <algorithm>
#include <cctype>

#include <boost/asio/ip/address.hpp>

namespace epviz::serve {
namespace {

std::string lowered(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::optional<boost::asio::ip::address> address_of(const std::string& host) {
  boost::system::error_code ec;
  const auto address = boost::asio::ip::make_address(host, ec);
  if (ec) return std::nullopt;
  return address;
}

bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
}

// Shown in log lines and 403 bodies: bounded, one line, printable.
std::string quoted(std::string_view text) {
  std::string out = "'";
  for (char c : text.substr(0, 100)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  if (text.size() > 100) out += "...";
  return out + "'";
}

std::string with_brackets(const std::string& host) {
  return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

}  // namespace

OriginPolicy::OriginPolicy(std::string bind, unsigned short port,
                           const std::vector<std::string>& allowed)
    : port_(port) {
  bind = lowered(bind);
  if (bind.size() > 2 && bind.front() == '[' && bind.back() == ']')
    bind = bind.substr(1, bind.size() - 2);
  bind_ = bind;
  const auto address = address_of(bind_);
  loopback_ = bind_ == "localhost" || (address && address->is_loopback());
  wildcard_ = address && address->is_unspecified();
  for (const std::string& origin : allowed) {
    if (const auto split = split_origin(origin)) {
      allowed_.push_back(*normalize_origin(origin));
      allowed_hosts_.push_back(split->second);
    }
  }
}

std::optional<OriginPolicy::Authority> OriginPolicy::parse_authority(std::string_view text,
                                                                     unsigned short fallback) {
  Authority a;
  std::string_view rest;
  if (!text.empty() && text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string_view::npos) return std::nullopt;
    a.host = lowered(text.substr(1, close - 1));
    const auto address = address_of(a.host);
    if (!address || !address->is_v6()) return std::nullopt;
    rest = text.substr(close + 1);
  } else {
    const auto colon = text.find(':');
    a.host = lowered(text.substr(0, colon));
    if (a.host.empty() || !std::all_of(a.host.begin(), a.host.end(), is_name_char))
      return std::nullopt;
    rest = colon == std::string_view::npos ? std::string_view() : text.substr(colon);
  }
  if (rest.empty()) {
    a.port = fallback;
    return a;
  }
  if (rest.front() != ':' || rest.size() < 2 || rest.size() > 6) return std::nullopt;
  unsigned long port = 0;
  for (char c : rest.substr(1)) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    port = port * 10 + static_cast<unsigned long>(c - '0');
  }
  if (port == 0 || port > 65535) return std::nullopt;
  a.port = static_cast<unsigned short>(port);
  return a;
}

std::optional<std::pair<std::string, OriginPolicy::Authority>> OriginPolicy::split_origin(
    std::string_view origin) {
  const auto sep = origin.find("://");
  if (sep == std::string_view::npos) return std::nullopt;
  const std::string scheme = lowered(origin.substr(0, sep));
  unsigned short default_port = 0;
  if (scheme == "http")
    default_port = 80;
  else if (scheme == "https")
    default_port = 443;
  else
    return std::nullopt;
  const auto authority = parse_authority(origin.substr(sep + 3), default_port);
  if (!authority) return std::nullopt;
  return std::make_pair(scheme, *authority);
}

std::optional<std::string> OriginPolicy::normalize_origin(std::string_view origin) {
  const auto split = split_origin(origin);
  if (!split) return std::nullopt;
  const auto& [scheme, a] = *split;
  const bool default_port =
      (scheme == "http" && a.port == 80) || (scheme == "https" && a.port == 443);
  // Appended piecewise: GCC 12 warns (-Wrestrict, a false positive) on "literal" + string&&.
  std::string out = scheme;
  out += "://";
  out += with_brackets(a.host);
  if (!default_port) {
    out += ':';
    out += std::to_string(a.port);
  }
  return out;
}

bool OriginPolicy::names_this_server(const Authority& a) const {
  for (const Authority& allowed : allowed_hosts_)
    if (allowed.host == a.host && allowed.port == a.port) return true;
  if (a.port != port_) return false;
  if (a.host == bind_) return true;
  const auto address = address_of(a.host);
  if (loopback_ && (a.host == "localhost" || (address && address->is_loopback()))) return true;
  // Behind a wildcard address any of the machine's addresses may be used,
  // but a name could be anyone's: only literals (and localhost) pass.
  if (wildcard_ && (a.host == "localhost" || address)) return true;
  return false;
}

std::optional<std::string> OriginPolicy::host_problem(std::string_view host) const {
  if (host.empty()) return "no Host header";
  const auto authority = parse_authority(host, 80);
  if (!authority || !names_this_server(*authority))
    return "Host " + quoted(host) + " does not name this server (" + with_brackets(bind_) + ":" +
           std::to_string(port_) + ")";
  return std::nullopt;
}

std::optional<std::string> OriginPolicy::origin_problem(bool present, std::string_view origin,
                                                        std::string_view host) const {
  if (!present) return std::nullopt;
  const auto normalized = normalize_origin(origin);
  if (normalized && std::find(allowed_.begin(), allowed_.end(), *normalized) != allowed_.end())
    return std::nullopt;
  const auto split = split_origin(origin);
  const auto host_authority = parse_authority(host, 80);
  if (split && split->first == "http" && names_this_server(split->second)) {
    if (!wildcard_) return std::nullopt;
    if (host_authority && host_authority->host == split->second.host &&
        host_authority->port == split->second.port)
      return std::nullopt;
  }
  return "Origin " + quoted(origin) +
         " is not this server's page (allow it with --allow-origin if that is meant)";
}

}  // namespace epviz::serve
