#include "shard/shard_spec.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <utility>
#include <vector>

namespace epviz::shard {
namespace {

// A non-negative decimal integer up to `max`, nothing else (no sign, no spaces).
std::optional<long> whole_number(std::string_view s, long max) {
  if (s.empty() || s.size() > 12) return std::nullopt;
  long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || v < 0 || v > max) return std::nullopt;
  return v;
}

std::string quoted_text(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
  return "'" + out + (s.size() > 40 ? "...'" : "'");
}

}  // namespace

ShardSpec parse_shard(std::string_view text, const std::string& option) {
  const auto slash = text.find('/');
  const auto fail = [&] {
    throw ShardError(option + ": expected I/N with 0 <= I < N <= " + std::to_string(max_shards) +
                     " (shard I of N, counted from 0), got " + quoted_text(text));
  };
  if (slash == std::string_view::npos) fail();
  const auto i = whole_number(text.substr(0, slash), max_shards);
  const auto n = whole_number(text.substr(slash + 1), max_shards);
  if (!i || !n || *n < 1 || *i >= *n) fail();
  return {*i, *n};
}

Environment process_environment() {
  return [](const std::string& name) -> std::optional<std::string> {
    const char* v = std::getenv(name.c_str());
    if (!v) return std::nullopt;
    return std::string(v);
  };
}

std::optional<ShardSpec> shard_from_environment(const Environment& env, long count_option) {
  auto number = [&](const std::string& name, long max) -> long {
    const auto v = env(name);
    const auto n = v ? whole_number(*v, max) : std::nullopt;
    if (!n)
      throw ShardError(name + ": expected a whole number from 0 to " + std::to_string(max) +
                       ", got " + (v ? quoted_text(*v) : std::string("nothing (unset)")));
    return *n;
  };
  // Each variable that is set says which shard this task is: the index
  // variables of the other schedulers must then say the same (a job started
  // by one scheduler inside another's task, or a variable left from a test),
  // else the task would run some other task's share.
  std::vector<std::pair<std::string, long>> said;  // "NAME=value", the shard it says
  std::optional<ShardSpec> chosen;
  if (env("SLURM_ARRAY_TASK_ID")) {
    const long id = number("SLURM_ARRAY_TASK_ID", 1'000'000'000);
    const long count = number("SLURM_ARRAY_TASK_COUNT", max_shards);
    const long min =
        env("SLURM_ARRAY_TASK_MIN") ? number("SLURM_ARRAY_TASK_MIN", 1'000'000'000) : 0;
    // A stepped array (--array=0-15:4) or a list (--array=1,3,7) numbers
    // its tasks with gaps: they are not shards 0..count-1.
    const long max = env("SLURM_ARRAY_TASK_MAX") ? number("SLURM_ARRAY_TASK_MAX", 1'000'000'000)
                                                 : min + count - 1;
    if (max - min + 1 != count)
      throw ShardError("SLURM_ARRAY_TASK_COUNT: " + std::to_string(count) + " tasks numbered " +
                       std::to_string(min) + " to " + std::to_string(max) +
                       " are not consecutive; give the array as --array=A-B (step 1) or pass "
                       "--shard I/N");
    // --shard-count is for the environments that give only an index; with
    // Slurm it may only say the same as the array (a script that passes it
    // everywhere), never another count: that would run the wrong share.
    if (count_option >= 1 && count_option != count)
      throw ShardError("--shard-count " + std::to_string(count_option) +
                       " disagrees with SLURM_ARRAY_TASK_COUNT " + std::to_string(count) +
                       ": give the array as many tasks as shards, or pass --shard I/N");
    if (count < 1 || id < min || id - min >= count)
      throw ShardError("SLURM_ARRAY_TASK_ID: task " + std::to_string(id) + " is not one of the " +
                       std::to_string(count) + " tasks from " + std::to_string(min) +
                       " (give the array as --array=A-B with step 1, or pass --shard I/N)");
    chosen = ShardSpec{id - min, count};
    said.emplace_back("SLURM_ARRAY_TASK_ID=" + std::to_string(id) +
                          (min ? " (from " + std::to_string(min) + ")" : std::string()),
                      id - min);
  }
  for (const char* name : {"JOB_COMPLETION_INDEX", "AWS_BATCH_JOB_ARRAY_INDEX"}) {
    if (!env(name)) continue;
    const long id = number(name, max_shards);
    said.emplace_back(std::string(name) + "=" + std::to_string(id), id);
    if (chosen) continue;
    if (count_option < 1)
      throw ShardError(std::string(name) +
                       " is set but the number of shards is not known: pass --shard-count N "
                       "(the job's completions or array size), or --shard I/N");
    if (id >= count_option)
      throw ShardError(std::string(name) + ": index " + std::to_string(id) +
                       " is not below --shard-count " + std::to_string(count_option));
    chosen = ShardSpec{id, count_option};
  }
  for (const auto& [what, index] : said)
    if (index != said.front().second)
      throw ShardError(said.front().first + " and " + what +
                       " disagree on which shard this task runs; unset the variable of the "
                       "scheduler that did not start it, or pass --shard I/N");
  return chosen;
}

std::optional<ShardSpec> shard_from_options(const std::string& shard_option,
                                            const std::string& count_option,
                                            const Environment& env) {
  long count = 0;
  if (!count_option.empty()) {
    const auto n = whole_number(count_option, max_shards);
    if (!n || *n < 1)
      throw ShardError("--shard-count: expected a whole number from 1 to " +
                       std::to_string(max_shards) + ", got " + quoted_text(count_option));
    count = *n;
  }
  if (shard_option.empty()) return shard_from_environment(env, count);
  const auto s = parse_shard(shard_option, "--shard");
  if (count && count != s.count)
    throw ShardError("--shard-count: " + std::to_string(count) + " disagrees with --shard " +
                     quoted_text(shard_option) + "; give one of them");
  return s;
}

ItemRange shard_range(long total, const ShardSpec& s) {
  // The first total % N shards take one item more; no product can overflow.
  const long q = total / s.count, r = total % s.count;
  auto at = [&](long i) { return i * q + std::min(i, r); };
  return {at(s.index), at(s.index + 1)};
}

std::string shard_tag(const ShardSpec& s) {
  return "shard-" + std::to_string(s.index) + "-of-" + std::to_string(s.count);
}

}  // namespace epviz::shard
