#include "shard/merged_rows.hpp"

#include <algorithm>
#include <fstream>
#include <set>

#include "io/bad_input.hpp"

namespace epviz::shard {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

std::vector<Json> read_rows(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<Json> rows;
  std::string line;
  long n = 0;
  while (std::getline(in, line)) {
    ++n;
    try {
      rows.push_back(Json::parse(line));
    } catch (const Json::exception&) {
      throw io::BadInput(file.string() + ": line " + std::to_string(n) + " is not a JSON row");
    }
  }
  return rows;
}

}  // namespace

std::vector<Json> merged_rows(const Batch& b, const fs::path& dir) {
  std::vector<Json> rows;
  std::set<long> seen;
  for (const auto& [i, m] : b.shards) {
    for (const auto& f : m.files) {
      for (auto& r : read_rows(dir / f.path)) {
        const long index = r.is_object() ? r.value("index", -1L) : -1L;
        if (index < m.items.first || index >= m.items.end || r.value("sweep", "") != b.hash)
          throw io::BadInput((dir / f.path).string() + ": a row (index " + std::to_string(index) +
                             ") that is not one of shard " + std::to_string(i) + "'s points");
        if (!seen.insert(index).second)
          throw io::BadInput((dir / f.path).string() + ": point " + std::to_string(index) +
                             " twice");
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
