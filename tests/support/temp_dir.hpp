#pragma once
// A fresh, empty directory for one test, removed with everything in it when
// the test ends (even what the test made unreadable), and reading a file whole.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

namespace epviz::test {

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class TempDir {
 public:
  // Named after the running test, so that a directory left by a crash says
  // whose it was; mkdtemp makes it unique among tests running side by side.
  TempDir() {
    std::string name = "epviz-test";
    if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
      name += std::string("-") + info->test_suite_name() + "-" + info->name();
    // Parameterised tests' names hold '/', which would make nested directories.
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    name = name.substr(0, 120) + "-XXXXXX";
    std::string pattern = (std::filesystem::temp_directory_path() / name).string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("cannot create a temporary directory " + pattern);
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    make_removable(path_);
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  std::size_t file_count() const {
    return std::size_t(std::distance(std::filesystem::directory_iterator(path_), {}));
  }
  // Writes `text` (as bytes) to the file `name` in this directory; its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name, std::ios::binary) << text;
    return path_ / name;
  }
  // `text` with every "{dir}" replaced by this directory's path.
  std::string expand(std::string text) const {
    for (std::size_t p; (p = text.find("{dir}")) != std::string::npos;)
      text.replace(p, 5, path_.string());
    return text;
  }

 private:
  // Tests take permissions away to provoke errors; give them back to the owner.
  static void make_removable(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add, ec);
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      if (it->is_directory(ec) && !it->is_symlink(ec)) make_removable(it->path());
  }

  std::filesystem::path path_;
};

// A fixture whose tests each get a TempDir, as dir_.
class TempDirTest : public ::testing::Test {
 protected:
  TempDir tmp_;
  const std::filesystem::path dir_ = tmp_.path();
};

}  // namespace epviz::test
