#include "fapcast/codec/fapu_values.hpp"

#include "fapcast/codec/feature_point.hpp"
#include "fapcast/core/frame_rate.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

FeaturePointPositions neutral_face(double scale) {
  FeaturePointPositions fp;
  fp[{9, 15}] = scale * Eigen::Vector3d(0, -2.0, 10);  // nose bottom
  fp[{2, 2}] = scale * Eigen::Vector3d(0, -5.0, 10);   // upper inner mid-lip
  fp[{8, 3}] = scale * Eigen::Vector3d(2.5, -5.5, 9);  // left lip corner (face's left: +x)
  fp[{8, 4}] = scale * Eigen::Vector3d(-2.5, -5.5, 9);
  fp[{3, 5}] = scale * Eigen::Vector3d(3.2, 3.0, 8);  // left pupil
  fp[{3, 6}] = scale * Eigen::Vector3d(-3.2, 3.0, 8);
  fp[{3, 1}] = scale * Eigen::Vector3d(3.2, 3.5, 8.5);  // upper left eyelid
  fp[{3, 3}] = scale * Eigen::Vector3d(3.2, 2.5, 8.5);  // lower left eyelid
  return fp;
}

TEST(Fapu, MeasuredFromFeaturePoints) {
  const FapuValues f = measure_fapu(neutral_face(1.0));
  EXPECT_DOUBLE_EQ(f.mns, 3.0 / 1024);
  EXPECT_DOUBLE_EQ(f.mw, 5.0 / 1024);
  EXPECT_DOUBLE_EQ(f.ens, 5.0 / 1024);
  EXPECT_DOUBLE_EQ(f.es, 6.4 / 1024);
  EXPECT_DOUBLE_EQ(f.irisd, 1.0 / 1024);
  EXPECT_DOUBLE_EQ(f.of(Fapu::kAU), 1e-5);
  EXPECT_DOUBLE_EQ(f.of(Fapu::kMW), f.mw);
}

TEST(Fapu, ScalesWithTheFaceAtExtremeScales) {
  const FapuValues one = measure_fapu(neutral_face(1.0));
  for (double s : {1e-8, 1e-3, 10.0, 1e8}) {
    const FapuValues f = measure_fapu(neutral_face(s));
    EXPECT_NEAR(f.mns / one.mns, s, s * 1e-12);
    EXPECT_NEAR(f.irisd / one.irisd, s, s * 1e-12);
  }
}

TEST(Fapu, MissingPointOrMirroredFaceIsNamed) {
  auto face = neutral_face(1.0);
  face.erase({8, 4});
  try {
    measure_fapu(face);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("8.4"), std::string::npos) << e.what();
  }
  auto mirrored = neutral_face(1.0);
  for (auto& [fp, p] : mirrored) p.x() = -p.x();
  EXPECT_THROW(measure_fapu(mirrored), std::invalid_argument);
}

TEST(FeaturePoint, ParsesAndPrintsLabels) {
  EXPECT_EQ(parse_feature_point("2.1"), (FeaturePoint{2, 1}));
  EXPECT_EQ(parse_feature_point("9.15")->label(), "9.15");
  for (const char* bad : {"", "2", "2.", ".1", "1.1", "12.1", "2.0", "2.1.1", "a.b", "2.100"})
    EXPECT_FALSE(parse_feature_point(bad).has_value()) << bad;
}

TEST(FrameRate, FramesLandOnTheSampleTimelineWithoutDrift) {
  const FrameRate ntsc{30000, 1001};
  // One hour of 29.97 fps at 48 kHz: the last frame is exactly where rational arithmetic puts it.
  const std::int64_t k = 107892;  // frames in one hour at 30000/1001
  EXPECT_EQ(frame_to_sample(k, ntsc, SampleRate{48000}), 172799827);
  for (std::int64_t f : {0, 1, 2, 999, 107891}) {
    const auto s = frame_to_sample(f, ntsc, SampleRate{48000});
    EXPECT_EQ(sample_to_frame(s, ntsc, SampleRate{48000}), f);
    EXPECT_EQ(sample_to_frame(s - 1, ntsc, SampleRate{48000}), f == 0 ? 0 : f - 1);
  }
  EXPECT_EQ(frame_to_sample(3, FrameRate{25, 1}, SampleRate{22050}), 2646);
  EXPECT_EQ((FrameRate{50, 2}), (FrameRate{25, 1}));
}

}  // namespace
}  // namespace fapcast
