#include "shard/merged_rows.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "io/bad_input.hpp"
#include "io/json_reader.hpp"
#include "io/json_text.hpp"
#include "io/printable.hpp"

namespace epviz::shard {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

// The rows of `file`, each an object with an integer "index" and a string
// "sweep": what the merge sorts and checks by, so that a hostile row is a
// message naming the file and line, not an exception of the JSON library.
std::vector<Json> read_rows(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<Json> rows;
  std::string line;
  long n = 0;
  const std::string name = io::printable(file.string(), 300);  // one line in messages
  while (std::getline(in, line)) {
    ++n;
    Json row;
    try {
      row = io::parse_json(line);
    } catch (const Json::exception&) {
      throw io::BadInput(name + ": line " + std::to_string(n) + " is not a JSON row");
    }
    if (!row.is_object() || !row.contains("index") || !row["index"].is_number_integer() ||
        !row.contains("sweep") || !row["sweep"].is_string())
      throw io::BadInput(name + ": line " + std::to_string(n) +
                         ": expected an object with an integer \"index\" and a string "
                         "\"sweep\", got " +
                         io::describe(row));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

bool same_row(const Json& a, const Json& b) {
  if (!a.is_object() || !b.is_object()) return a == b;
  Json a_result = a, b_result = b;
  a_result.erase("cpu_seconds");
  b_result.erase("cpu_seconds");
  return a_result == b_result;
}

std::vector<Json> merged_rows(const Batch& b, const fs::path& dir, const RowCheck& check) {
  std::vector<Json> rows;
  std::vector<std::string> names;  // of the files read, for messages
  struct Seen {
    std::size_t row;   // in `rows`
    std::size_t name;  // in `names`
    std::size_t line;
  };
  std::map<long, Seen> seen;  // by index
  const auto where = [&](const Seen& s) {
    return names[s.name] + ": line " + std::to_string(s.line);
  };
  for (const auto& [i, m] : b.shards) {
    for (const auto& f : m.files) {
      names.push_back(io::printable((dir / f.path).string(), 300));
      auto file_rows = read_rows(dir / f.path);
      for (std::size_t k = 0; k < file_rows.size(); ++k) {
        auto& r = file_rows[k];
        const long index = r["index"].get<long>();
        if (index < m.items.first || index >= m.items.end || r["sweep"] != b.hash)
          throw io::BadInput(names.back() + ": a row (index " + std::to_string(index) +
                             ") that is not one of shard " + std::to_string(i) + "'s points");
        const Seen here{rows.size(), names.size() - 1, k + 1};
        if (check)
          if (const std::string problem = check(r); !problem.empty())
            throw io::BadInput(where(here) + ": " + problem);
        const auto [it, first] = seen.try_emplace(index, here);
        if (!first) {
          if (!same_row(rows[it->second.row], r))
            throw io::BadInput(where(it->second) + " and " + where(here) +
                               ": two different rows of point " + std::to_string(index) +
                               "; remove the wrong one, or the shard's files to run it again");
          continue;  // the same row twice: once is enough
        }
        rows.push_back(std::move(r));
      }
    }
    for (long k = m.items.first; k < m.items.end; ++k)
      if (!seen.count(k))
        throw io::BadInput("shard " + std::to_string(i) + "/" + std::to_string(b.count) +
                           ": point " + std::to_string(k) +
                           " has no row; run: " + rerun_command(m, i));
  }
  std::sort(rows.begin(), rows.end(), [](const Json& a, const Json& c) {
    return a["index"].get<long>() < c["index"].get<long>();
  });
  return rows;
}

}  // namespace epviz::shard
