// A render job's "cloud": read strictly and written back; a bad member count
// or radius is refused by `epviz render` with exit 2 and one line naming the
// key, before anything is drawn.
#include <gtest/gtest.h>

#include "io/bad_input.hpp"
#include "job/schema.hpp"
#include "support/cli.hpp"

namespace epviz {
namespace {

using test::TempDir;

std::string job_text(const TempDir& dir, const std::string& cloud) {
  std::string s = R"({"simulation": {"case": "generic", "t_end": 2}, "cloud": )";
  s += cloud;
  s += R"(, "width": 64, "height": 48, "fps": 2, "duration": 1, "output": {"dir": ")";
  s += (dir / "out").string();
  s += R"(", "format": "png"}})";
  return s;
}

TEST(CloudKey, ReadsAndWritesBack) {
  const auto j = nlohmann::json::parse(
      R"({"simulation": {"case": "generic"}, "cloud": {"members": 300, "radius": 0.02}})");
  const auto doc = job::read_job(j, "job.json");
  EXPECT_EQ(doc.scene.cloud.members, 300);
  EXPECT_EQ(doc.scene.cloud.radius, 0.02);
  const auto back = job::read_job(nlohmann::json::parse(job::write_job(doc).dump()), "job.json");
  EXPECT_EQ(back.scene.cloud.members, 300);
  EXPECT_EQ(back.scene.cloud.radius, 0.02);
  // An empty object asks for the defaults; no key, for no cloud.
  const auto plain = job::read_job(
      nlohmann::json::parse(R"({"simulation": {"case": "generic"}, "cloud": {}})"), "job.json");
  EXPECT_EQ(plain.scene.cloud.members, scene::kDefaultCloudMembers);
  const auto none =
      job::read_job(nlohmann::json::parse(R"({"simulation": {"case": "generic"}})"), "job.json");
  EXPECT_FALSE(none.scene.cloud.enabled());
  EXPECT_FALSE(job::write_job(none).contains("cloud"));
}

TEST(CloudKey, BadValuesExitTwoNamingTheKey) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"members": 0})", "key 'cloud.members'"},
      {R"({"members": 100001})", "key 'cloud.members'"},
      {R"({"members": 2.5})", "key 'cloud.members'"},
      {R"({"radius": -0.1})", "key 'cloud.radius'"},
      {R"({"radius": 0})", "key 'cloud.radius'"},
      {R"({"radius": 2})", "key 'cloud.radius'"},
      {R"({"size": 3})", "cloud.size"},
      {R"(7)", "key 'cloud'"},
  };
  for (const auto& [cloud, named] : cases) {
    SCOPED_TRACE(cloud);
    TempDir dir;
    test::expect_render_refused(dir, job_text(dir, cloud), "--quiet", dir / "out", named);
  }
}

TEST(CloudKey, MembersThatCannotKeepTheEnergyAreRefusedBeforeAnyWork) {
  TempDir dir;
  std::string job = R"({"simulation": {"case": "generic", "t_end": 2, "omega": [0, 0, 0]}, )";
  job += R"("cloud": {"members": 10}, "width": 64, "height": 48, "fps": 2, "duration": 1, )";
  job += R"("output": {"dir": ")" + (dir / "out").string() + R"(", "format": "png"}})";
  test::expect_render_refused(dir, job, "--quiet", dir / "out", "cloud");
}

}  // namespace
}  // namespace epviz
