#pragma once
// Which part of a batch one process does: shard I of N (I from 0), given on
// the command line ("--shard 2/8") or by the array job that started the
// process (Slurm, Kubernetes Indexed Jobs, AWS Batch). A shard is a
// contiguous range of items, so that its output is a contiguous slice of the
// whole and merging is concatenation in shard order.
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "io/bad_input.hpp"

namespace epviz::shard {

// A malformed or impossible shard: the message names the option or variable
// and says what is allowed.
class ShardError : public io::BadInput {
 public:
  using io::BadInput::BadInput;
};

inline constexpr long max_shards = 1'000'000;

struct ShardSpec {
  long index = 0;  // 0 .. count-1
  long count = 1;
  bool operator==(const ShardSpec&) const = default;
};

// "I/N" with 0 <= I < N <= max_shards; `option` names it in messages.
ShardSpec parse_shard(std::string_view text, const std::string& option = "--shard");

// Reads a variable of the environment; nullopt when unset. Tests pass their own.
using Environment = std::function<std::optional<std::string>(const std::string& name)>;
Environment process_environment();

// The shard an array job gives this process, or nullopt outside an array job:
//   Slurm:      SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN of SLURM_ARRAY_TASK_COUNT
//               (an array --array=1-4 numbers its tasks from 1)
//   Kubernetes: JOB_COMPLETION_INDEX of `count_option` (the Job's completions)
//   AWS Batch:  AWS_BATCH_JOB_ARRAY_INDEX of `count_option` (the array size)
// The last two do not say how many tasks there are: `count_option` (the value
// of --shard-count, 0 when not given) must; with Slurm it must agree with
// SLURM_ARRAY_TASK_COUNT. Throws ShardError for values that do not make a
// shard, naming the variable.
std::optional<ShardSpec> shard_from_environment(const Environment& env, long count_option);

// The shard this process does, from the options of `epviz sweep` and `epviz
// render`: --shard I/N (`shard_option`) when given, else the array job's
// environment, with --shard-count N (`count_option`; "" when not given) for
// the environments that give only the index; nullopt: the whole batch.
// Throws ShardError naming the option or variable.
std::optional<ShardSpec> shard_from_options(const std::string& shard_option,
                                            const std::string& count_option,
                                            const Environment& env = process_environment());

// Items [first, end) of `total` that shard `s` does: sizes differ by at most one.
struct ItemRange {
  long first = 0;
  long end = 0;
  long size() const { return end - first; }
  bool operator==(const ItemRange&) const = default;
};
ItemRange shard_range(long total, const ShardSpec& s);

// "shard-2-of-8", the piece shard files are named with.
std::string shard_tag(const ShardSpec& s);

}  // namespace epviz::shard
