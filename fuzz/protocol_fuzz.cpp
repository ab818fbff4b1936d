// A page's WebSocket text message (docs/serve.md) through the server's parser,
// and any bytes through the decoder of server messages. Malformed input must
// end in ProtocolError (which closes only that connection), never in a crash;
// a message that parses must parse again, unchanged, once encoded.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>

#include "serve/protocol.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace epviz::serve;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const std::string encoded = encode_client_message(parse_client_message(text));
    if (encode_client_message(parse_client_message(encoded)) != encoded) std::abort();
  } catch (const ProtocolError&) {
  }
  try {
    (void)decode_server_message(std::span<const std::uint8_t>(data, size));
  } catch (const ProtocolError&) {
  }
  return 0;
}
