// JSON documents through the strict reader, grown wide and deep from the
// fuzzer's bytes: the input's first two bytes set how many times the rest
// (an element, whatever it holds) is repeated in one array, the third how
// deep that array is nested, so that a few bytes make the documents whose
// reading once took time quadratic in their width. scripts/fuzz.sh gives
// this target a time bound per input of 2 s: a slow input is a finding.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "io/bad_input.hpp"
#include "io/json_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  const std::size_t copies = 1 + ((std::size_t(data[0]) << 8) | data[1]) % 60'000;
  const std::size_t depth = data[2] % 70;
  const std::string_view element(reinterpret_cast<const char*>(data) + 3, size - 3);
  std::string text = R"({"rows": )";
  text.append(depth, '[');
  text += '[';
  for (std::size_t i = 0; i < copies && text.size() < (std::size_t{2} << 20); ++i) {
    if (i) text += ',';
    text += element;
  }
  text += ']';
  text.append(depth, ']');
  text += '}';
  try {
    epviz::io::parse_json_text(text, "fuzz.json");
  } catch (const epviz::io::BadInput&) {
  }
  return 0;
}
