// Cross-check with Blender's own BVH importer: the file imports, and every bone's world position
// at every frame equals fapcast's forward kinematics. Runs only where `blender` is on PATH.
#include "fapcast/codec/bvh_export.hpp"
#include "fapcast/codec/bvh_text.hpp"
#include "support/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace fapcast {
namespace {

TEST(BvhBlender, BlenderImportsTheExportAndPosesEveryBoneWhereWeDo) {
  if (test::run_command("command -v blender").exit_code != 0)
    GTEST_SKIP() << "blender is not on PATH (Debian package `blender`); this cross-check needs it";

  FapSequence seq{"blender", {25, 1}, {}};
  for (int k = 0; k < 6; ++k) {  // jaw, head, lips, tongue all moving at once
    FapFrame f;
    f.set(3, 150 * k).set(15, -20 * k).set(14, 10 * k);
    f.set(48, 2500 * k).set(49, -1500 * k).set(50, 800 * k);
    f.set(5, -40 * k).set(53, 60 * k).set(59, 30 * k).set(17, 25 * k).set(44, 70 * k);
    seq.frames.push_back(f);
  }
  const BvhDocument doc = fap_to_bvh(seq, generic_adult_face());
  const std::string dir = test::make_temp_dir("bvh-blender");
  const std::string path = dir + "/face.bvh";
  std::ofstream(path) << write_bvh(doc);

  const auto r = test::run_command(
      "blender -b --factory-startup --python '" FAPCAST_SOURCE_DIR
      "/tests/data/bvh/blender_import_check.py' -- '" + path + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  ASSERT_NE(r.out.find("IMPORTED face 19 bones"), std::string::npos) << r.out;
  ASSERT_NE(r.out.find("fps 25.0"), std::string::npos) << r.out;

  std::map<std::pair<std::uint64_t, std::string>, Eigen::Vector3d> blender;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream in(line);
    std::string tag, name;
    std::uint64_t k = 0;
    Eigen::Vector3d p;
    if (in >> tag >> k >> name >> p.x() >> p.y() >> p.z() && tag == "POS") blender[{k, name}] = p;
  }
  ASSERT_EQ(blender.size(), doc.frame_count * doc.joints.size()) << r.out;
  for (std::uint64_t k = 0; k < doc.frame_count; ++k) {
    const auto world = joint_world_transforms(doc, k);
    for (std::size_t j = 0; j < doc.joints.size(); ++j) {
      const Eigen::Vector3d& theirs = blender.at({k, doc.joints[j].name});
      EXPECT_LT((theirs - world[j].translation()).norm(), 1e-4)
          << "frame " << k << " joint " << doc.joints[j].name << ": blender "
          << theirs.transpose() << ", fapcast " << world[j].translation().transpose();
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fapcast
