// Which Host and Origin headers name the server, decided without sockets:
// the bound address and port, loopback's other names, wildcard binds (address
// literals only, never a name that could be rebound) and --allow-origin.
#include <gtest/gtest.h>

#include "serve/origin_policy.hpp"

namespace epviz::serve {
namespace {

bool host_ok(const OriginPolicy& p, const char* host) { return !p.host_problem(host); }
bool origin_ok(const OriginPolicy& p, const char* origin, const char* host = "127.0.0.1:8080") {
  return !p.origin_problem(true, origin, host);
}

TEST(OriginPolicy, LoopbackAcceptsItsOwnNamesOnItsPortOnly) {
  const OriginPolicy p("127.0.0.1", 8080, {});
  for (const char* host : {"127.0.0.1:8080", "localhost:8080", "LOCALHOST:8080", "[::1]:8080"})
    EXPECT_TRUE(host_ok(p, host)) << host;
  for (const char* host : {"evil.example:8080", "127.0.0.1:8081", "127.0.0.1", "localhost.:8080",
                           "", "127.0.0.1:80800", "127.0.0.1:0", "a b:8080", "[::1:8080",
                           "evil.example:8080@127.0.0.1:8080"})
    EXPECT_FALSE(host_ok(p, host)) << host;
}

TEST(OriginPolicy, OwnOriginsAcceptedOthersRefused) {
  const OriginPolicy p("127.0.0.1", 8080, {});
  for (const char* origin : {"http://127.0.0.1:8080", "http://localhost:8080", "http://[::1]:8080",
                             "HTTP://LocalHost:8080"})
    EXPECT_TRUE(origin_ok(p, origin)) << origin;
  for (const char* origin :
       {"http://evil.example", "http://evil.example:8080", "https://127.0.0.1:8080",
        "http://127.0.0.1:9999", "http://127.0.0.1", "null", "", "file://", "127.0.0.1:8080",
        "http://127.0.0.1:8080/path", "http://user@127.0.0.1:8080"})
    EXPECT_FALSE(origin_ok(p, origin)) << origin;
  EXPECT_FALSE(p.origin_problem(false, "", "127.0.0.1:8080")) << "no Origin: not a web page";
  const auto problem = p.origin_problem(true, "http://evil.example", "127.0.0.1:8080");
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("'http://evil.example'"), std::string::npos) << *problem;
  EXPECT_NE(problem->find("--allow-origin"), std::string::npos) << *problem;
}

TEST(OriginPolicy, AllowedOriginsAreAcceptedWithTheirHosts) {
  const OriginPolicy p("127.0.0.1", 8080, {"https://viz.example.org", "http://Lab:3000"});
  EXPECT_TRUE(origin_ok(p, "https://viz.example.org"));
  EXPECT_TRUE(origin_ok(p, "https://viz.example.org:443"));
  EXPECT_TRUE(origin_ok(p, "http://lab:3000"));
  EXPECT_FALSE(origin_ok(p, "http://viz.example.org"));
  EXPECT_FALSE(origin_ok(p, "http://lab:3001"));
  // A reverse proxy for an allowed origin forwards its Host.
  EXPECT_TRUE(host_ok(p, "viz.example.org:443"));
  EXPECT_FALSE(host_ok(p, "viz.example.org:8080"));
}

TEST(OriginPolicy, NamedBindAcceptsThatNameOnly) {
  const OriginPolicy p("192.168.1.20", 9000, {});
  EXPECT_TRUE(host_ok(p, "192.168.1.20:9000"));
  EXPECT_FALSE(host_ok(p, "localhost:9000")) << "not bound to loopback";
  EXPECT_TRUE(origin_ok(p, "http://192.168.1.20:9000", "192.168.1.20:9000"));
  EXPECT_FALSE(origin_ok(p, "http://127.0.0.1:9000", "192.168.1.20:9000"));
}

TEST(OriginPolicy, WildcardBindAcceptsLiteralsNotNames) {
  const OriginPolicy p("0.0.0.0", 8080, {});
  EXPECT_TRUE(host_ok(p, "10.0.0.5:8080"));
  EXPECT_TRUE(host_ok(p, "localhost:8080"));
  EXPECT_TRUE(host_ok(p, "[fe80::1]:8080"));
  EXPECT_FALSE(host_ok(p, "rebind.evil.example:8080"));
  EXPECT_FALSE(host_ok(p, "10.0.0.5:8081"));
  // The page must come from the host it connects to.
  EXPECT_TRUE(origin_ok(p, "http://10.0.0.5:8080", "10.0.0.5:8080"));
  EXPECT_FALSE(origin_ok(p, "http://10.0.0.9:8080", "10.0.0.5:8080"));
}

TEST(OriginPolicy, NormalizesOrigins) {
  EXPECT_EQ(OriginPolicy::normalize_origin("HTTP://Example.ORG:80"), "http://example.org");
  EXPECT_EQ(OriginPolicy::normalize_origin("https://x:8443"), "https://x:8443");
  EXPECT_EQ(OriginPolicy::normalize_origin("http://[::1]:8080"), "http://[::1]:8080");
  EXPECT_FALSE(OriginPolicy::normalize_origin("http://x/"));
  EXPECT_FALSE(OriginPolicy::normalize_origin("ws://x"));
  EXPECT_FALSE(OriginPolicy::normalize_origin("x:80"));
}

}  // namespace
}  // namespace epviz::serve
