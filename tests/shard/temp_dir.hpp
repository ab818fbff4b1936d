#pragma once
// A fresh directory for one test, removed with everything in it afterwards.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace epviz::shard::test {

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             ("epviz-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

}  // namespace epviz::shard::test
