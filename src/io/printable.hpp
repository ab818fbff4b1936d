#pragma once
// Text a user wrote (a key, a value, an argument), made fit to quote in a
// one-line error message: control characters escaped, invalid UTF-8 shown as
// bytes, and a long text cut short, so that no input can split the message
// over several lines or turn it into megabytes.
#include <cstddef>
#include <string>
#include <string_view>

namespace epviz::io {

// At most about `max_bytes` of `text`, with "\n", "\t", "\u0001", "\xff", ...
// for what a terminal would not print on one line; a text cut short ends in
// "... (N bytes)".
std::string printable(std::string_view text, std::size_t max_bytes = 60);

// How a message quotes a value it was given: printable(text, max_bytes) in
// single quotes ("'bo\\ngus'", "'xxx... (100000 bytes)'").
std::string quoted(std::string_view text, std::size_t max_bytes = 60);

}  // namespace epviz::io
