// The CI recipes of docs/ci.md install what epviz needs through the project's
// own set-up (scripts/setup.sh, directly or through scripts/build.sh), so that
// their package list cannot go stale; a recipe that installs packages itself
// may name only packages scripts/setup.sh --build installs (a package missing
// there, such as libegl-dev once, then fails here, not on a user's runner).
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/temp_dir.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

std::string source_file(const char* path) { return test::slurp(fs::path(EPVIZ_SOURCE_DIR) / path); }

// The ```yaml blocks of a Markdown text.
std::vector<std::string> yaml_blocks(const std::string& markdown) {
  std::vector<std::string> blocks;
  const std::regex block("```yaml\n([\\s\\S]*?)```");
  for (std::sregex_iterator it(markdown.begin(), markdown.end(), block), end; it != end; ++it)
    blocks.push_back((*it)[1]);
  return blocks;
}

// The words of the bash array `name=( ... )` in a script.
std::set<std::string> array_words(const std::string& script, const std::string& name) {
  const auto start = script.find("\n" + name + "=(");
  if (start == std::string::npos) return {};
  const auto open = script.find('(', start), close = script.find(')', open);
  std::istringstream words(script.substr(open + 1, close - open - 1));
  std::set<std::string> out;
  for (std::string w; words >> w;) out.insert(w);
  return out;
}

// What `scripts/setup.sh --build` installs: its runtime and build lists.
std::set<std::string> build_packages() {
  const auto setup = source_file("scripts/setup.sh");
  auto packages = array_words(setup, "runtime_packages");
  const auto build = array_words(setup, "build_packages");
  packages.insert(build.begin(), build.end());
  return packages;
}

// The packages `apt-get install` / `apt install` lines of a recipe name.
std::vector<std::string> installed_by(const std::string& recipe) {
  std::vector<std::string> packages;
  const std::regex install(R"(apt(?:-get)? +install\b([^\n]*))");
  for (std::sregex_iterator it(recipe.begin(), recipe.end(), install), end; it != end; ++it) {
    std::istringstream words((*it)[1].str());
    for (std::string w; words >> w;)
      if (w[0] != '-') packages.push_back(w);
  }
  return packages;
}

TEST(CiRecipes, InstallThroughTheProjectsSetUp) {
  const auto recipes = yaml_blocks(source_file("docs/ci.md"));
  ASSERT_EQ(recipes.size(), 2u) << "docs/ci.md: the GitHub Actions and GitLab recipes";
  const std::regex set_up(R"(scripts/build\.sh --epviz-only|scripts/setup\.sh --(runtime|build))");
  for (const auto& recipe : recipes)
    EXPECT_TRUE(std::regex_search(recipe, set_up)) << "no call of the project's set-up in\n"
                                                   << recipe;
  EXPECT_NE(
      source_file("scripts/build.sh").find("--epviz-only)\n    bash scripts/setup.sh --build"),
      std::string::npos)
      << "scripts/build.sh --epviz-only must install through scripts/setup.sh --build";
}

TEST(CiRecipes, NamePackagesOnlyFromTheSetUpLists) {
  const auto known = build_packages();
  ASSERT_TRUE(known.count("libegl-dev")) << "scripts/setup.sh's lists were not read";
  for (const char* needed : {"libegl-mesa0", "fonts-dejavu-core", "libegl-dev"})
    EXPECT_TRUE(known.count(needed)) << needed << " is not installed by scripts/setup.sh --build";
  for (const auto& recipe : yaml_blocks(source_file("docs/ci.md")))
    for (const auto& p : installed_by(recipe))
      EXPECT_TRUE(known.count(p)) << "docs/ci.md installs " << p
                                  << ", which scripts/setup.sh --build does not";
}

TEST(CiRecipes, TheListReaderSeesWhatARecipeInstalls) {
  // The parts above on a recipe that lists packages itself (as the recipes once did).
  const auto packages = installed_by(
      "    - apt-get update && apt-get install -y --no-install-recommends cmake libfoo-dev\n");
  EXPECT_EQ(packages, (std::vector<std::string>{"cmake", "libfoo-dev"}));
  EXPECT_FALSE(build_packages().count("libfoo-dev"));
}

}  // namespace
}  // namespace epviz
