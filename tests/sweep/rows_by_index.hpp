#pragma once
// A sweep's rows file read back for comparison: rows by point index, without
// what differs between two runs of the same point (their CPU time); a point
// written twice fails the test.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace epviz::testing {

inline std::map<long, nlohmann::json> rows_by_index(const std::filesystem::path& file) {
  std::map<long, nlohmann::json> rows;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    auto row = nlohmann::json::parse(line);
    row.erase("cpu_seconds");
    const long index = row["index"].get<long>();
    EXPECT_FALSE(rows.count(index)) << "point " << index << " twice in " << file;
    rows[index] = std::move(row);
  }
  return rows;
}

}  // namespace epviz::testing
