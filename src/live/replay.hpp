#pragma once
// Replays a recording made by `epviz serve --record FILE`: the page's
// messages in the order the server applied them, and a {"type":"render"}
// line wherever it rendered a frame. The same session calls happen in the
// same order, so the panels see the same clicks at the same places; with
// SessionOptions::fixed_clock the run is the same on every machine.
#include <istream>
#include <stdexcept>

#include "serve/session.hpp"

namespace epviz::live {

struct ReplayCounts {
  long messages = 0;
  long frames = 0;
};

// Throws std::runtime_error naming the line for a line that is not a page message.
ReplayCounts replay(serve::Session& session, std::istream& recording);

}  // namespace epviz::live
