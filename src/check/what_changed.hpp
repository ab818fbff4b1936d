#pragma once
// Why a job's frames no longer match its goldens, as far as golden.json can
// tell: the job file changed since the goldens were made (update them or
// revert the job), or the rendering did, and then which part of what draws
// (GL renderer, GL version, font) differs from what made the goldens.
#include <optional>
#include <string>
#include <vector>

#include "check/golden_record.hpp"

namespace epviz::check {

// One phrase per part of `now` that differs from what `record` holds, e.g.
// "font builtin in golden.json, DejaVuSans.ttf (fnv1a64:...) now". A part the
// record lacks (records of older epviz hold no font) is not compared. Text
// from golden.json is escaped and cut short.
std::vector<std::string> environment_differences(const GoldenRecord& record,
                                                 const RenderEnvironment& now);

// The cause given with every failing frame of a job, from its record
// (nullopt: no golden.json), its job file's file_hash now, and the command that
// re-baselines it:
//   "job changed since goldens: update or revert (update: CMD)"
//   "rendering changed, the job did not; differs from the goldens: PHRASES"
//   "rendering changed, the job did not (same GL renderer, GL version and font)"
std::string failure_cause(const std::optional<GoldenRecord>& record, const std::string& job_hash,
                          const RenderEnvironment& now, const std::string& update_command);

}  // namespace epviz::check
