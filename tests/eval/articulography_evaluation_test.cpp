#include "fapcast/eval/articulography_evaluation.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/marker_map.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace fapcast {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// A mesh (1 x 3N, metres) with only the face points set: the upper incisor at (y, z) = (0, 0),
// the nose dorsum on a straight line `nose_deg` forward of up, 70 mm (root) to 40 mm (tip) away.
RowMajorMatrixXf constructed_face(double nose_deg) {
  const ArticulographyFacePoints p = ict_articulography_points();
  RowMajorMatrixXf mesh = RowMajorMatrixXf::Zero(1, 3 * (p.lower_incisor + 1));
  const auto put = [&](std::int32_t v, double y_mm, double z_mm) {
    mesh(0, 3 * v + 1) = static_cast<float>(y_mm / 1000);
    mesh(0, 3 * v + 2) = static_cast<float>(z_mm / 1000);
  };
  const std::array<double, 4> distance{70, 60, 50, 40};
  for (std::size_t k = 0; k < 4; ++k)
    put(p.nose_dorsum[k], distance[k] * std::cos(nose_deg * kDeg), distance[k] * std::sin(nose_deg * kDeg));
  put(p.upper_lip, -2, 12);
  put(p.lower_lip, -14, 11);
  put(p.chin, -55, 8);
  put(p.lower_incisor, -9, -1);
  return mesh;
}

// The talker's motion in the true head frame (forward, up), mm, t in s.
double opening(double t) { return 4 + 3 * std::sin(2 * std::numbers::pi * 2 * t); }
double jaw(double t) { return 2 + std::sin(2 * std::numbers::pi * 1.5 * t + 0.3); }
double tip(double t) { return 3 * std::sin(2 * std::numbers::pi * 3 * t); }

// A MOCHA-like EMA at 500 Hz: the coils of a head whose ui -> bn vector is 13 deg forward of up
// (as the constructed face's nose) but recorded pitched back by `pitch_deg`, x pointing back,
// and offset by (3, -2) mm.
MarkerFrames<Millimetres> constructed_ema(double pitch_deg, Eigen::Index frames = 1000) {
  MarkerFrames<Millimetres> ema = MarkerFrames<Millimetres>::zeros(7, frames);
  ema.labels = {"ui", "li", "ul", "ll", "tt", "td", "bn"};
  ema.frame_rate_hz = 500;
  ema.first_frame = 0;
  const double c = std::cos(pitch_deg * kDeg), s = std::sin(pitch_deg * kDeg);
  for (Eigen::Index k = 0; k < frames; ++k) {
    const double t = static_cast<double>(k) / 500;
    const std::array<std::array<double, 2>, 7> fu{{{0, 0},
                                                   {-1, -8 - jaw(t)},
                                                   {10, 5},
                                                   {10, -5 - opening(t)},
                                                   {-12, -6 + tip(t)},
                                                   {-40, 0},
                                                   {57.7 * std::sin(13 * kDeg), 57.7 * std::cos(13 * kDeg)}}};
    for (std::size_t m = 0; m < fu.size(); ++m) {
      const auto [f, u] = fu[m];
      const double f2 = f * c - u * s, u2 = u * c + f * s;  // the angle from up turned by -pitch
      ema.set(static_cast<Eigen::Index>(m), k, Eigen::Vector3d(3 - f2, u2 - 2, 0));
    }
  }
  return ema;
}

TEST(ArticulographyEvaluation, FacePointsAreTheMarkerTablesFeaturePoints) {
  const ArticulographyFacePoints p = ict_articulography_points();
  EXPECT_EQ(p.upper_lip, marker_sites()[marker_row("8.1")].vertex);
  EXPECT_EQ(p.lower_lip, 5518);
  EXPECT_EQ(p.chin, 966);
  EXPECT_EQ(p.upper_incisor, 18075);
  EXPECT_EQ(p.lower_incisor, 20271);
}

// The incisor tips on the ICT face: on the midline, the upper one moved by no expression shape
// (the head frame's origin, like MOCHA's ui coil), the lower one carried down and back by jawOpen
// (40 mm at jawOpen = 1: an adult's maximal opening); the nose dorsum runs above them, and at
// fsew0_001's ui -> bn distance (57.7 mm) its point is 13 deg forward of up.
TEST(ArticulographyEvaluation, TheIncisorTipsAndTheNoseOfTheIctFace) {
  const FaceModel& face = ict_face_model();
  const ArticulographyFacePoints p = ict_articulography_points();
  const auto moved_by = [&](std::int32_t v, std::size_t k) {
    const auto& d = face.expressions[k].vertices;
    return std::binary_search(d.begin(), d.end(), v);
  };
  for (std::size_t k = 0; k < face.expressions.size(); ++k)
    EXPECT_FALSE(moved_by(p.upper_incisor, k)) << face.expression_names[k];
  const std::size_t jaw = face.expression_index("jawOpen");
  const auto& d = face.expressions[jaw];
  const auto at = std::lower_bound(d.vertices.begin(), d.vertices.end(), p.lower_incisor);
  ASSERT_TRUE(at != d.vertices.end() && *at == p.lower_incisor);
  const Eigen::Vector3f drop = d.offsets_cm.col(at - d.vertices.begin());
  EXPECT_NEAR(drop.norm(), 4.02, 0.05);
  EXPECT_LT(drop.y(), -3);
  EXPECT_LT(drop.z(), 0);
  EXPECT_LT(std::abs(face.neutral_cm(0, p.upper_incisor)), 0.15);
  EXPECT_LT(std::abs(face.neutral_cm(0, p.lower_incisor)), 0.15);
  // At rest the teeth are closed: the tips within a few mm (the lower ones overlap behind the upper).
  EXPECT_LT((face.neutral_cm.col(p.upper_incisor) - face.neutral_cm.col(p.lower_incisor)).norm(), 0.5);
  RowMajorMatrixXf mesh_m(1, 3 * face.vertex_count());
  for (std::int32_t v = 0; v < face.vertex_count(); ++v)
    for (int a = 0; a < 3; ++a) mesh_m(0, 3 * v + a) = face.neutral_cm(a, v) / 100;
  EXPECT_NEAR(face_nose_angle_rad(mesh_m, p, 57.7) / kDeg, 13.1, 0.2);
}

TEST(ArticulographyEvaluation, TheNosePointAnglesAreReadOffTheDorsum) {
  const RowMajorMatrixXf face = constructed_face(13);
  EXPECT_NEAR(face_nose_angle_rad(face, ict_articulography_points(), 57.7) / kDeg, 13, 1e-3);
  EXPECT_NEAR(face_nose_angle_rad(face, ict_articulography_points(), 90) / kDeg, 13, 1e-3);  // clamped to the root
  EXPECT_THROW(face_nose_angle_rad(RowMajorMatrixXf::Zero(1, 30), ict_articulography_points(), 50), std::invalid_argument);
}

// A known pitch is recovered, and the measures come out in the head frame whatever the pitch.
TEST(ArticulographyEvaluation, RegistrationRecoversAKnownPitchAndTheMeasures) {
  const RowMajorMatrixXf face = constructed_face(13);
  for (const double pitch : {25.0, -10.0, 0.0}) {
    const MarkerFrames<Millimetres> ema = constructed_ema(pitch);
    const EmaRegistration r = register_ema(ema, "head.ema", face, ict_articulography_points());
    EXPECT_EQ(r.forward_sign, -1);  // x points back
    EXPECT_NEAR(r.origin_x_mm, 3, 1e-9);
    EXPECT_NEAR(r.origin_y_mm, -2, 1e-9);
    EXPECT_NEAR(r.nose_distance_mm, 57.7, 1e-9);
    EXPECT_NEAR(r.coil_angle_rad / kDeg, 13 - pitch, 1e-6);
    EXPECT_NEAR(r.rotation_rad / kDeg, pitch, 1e-3);
    const MeasureCurves m = ema_measure_curves(ema, r, 100, 1.998);
    ASSERT_EQ(m.size(), 200u);
    for (std::size_t j = 10; j < 190; ++j) {  // away from the ends
      const double t = static_cast<double>(j) / 100;
      EXPECT_NEAR(m.mm[0][j], 10 + opening(t), 0.05) << pitch << " " << t;
      EXPECT_NEAR(m.mm[1][j], std::hypot(1.0, 8 + jaw(t)), 0.05) << t;
      EXPECT_NEAR(m.mm[2][j], 8 + jaw(t), 0.05) << t;
      EXPECT_NEAR(m.mm[3][j], 10, 0.01) << t;
      EXPECT_NEAR(m.mm[4][j], -6 + tip(t), 0.1) << t;  // 3 Hz: 4 % down at a 15 Hz cut-off
    }
  }
}

TEST(ArticulographyEvaluation, MissingCoilsAreRefusedByName) {
  const RowMajorMatrixXf face = constructed_face(13);
  MarkerFrames<Millimetres> ema = constructed_ema(0, 50);
  ema.labels[6] = "nose";  // no "bn"
  try {
    register_ema(ema, "head.ema", face, ict_articulography_points());
    FAIL() << "no bn coil accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "ema-coils");
    EXPECT_NE(std::string(e.what()).find("head.ema"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'bn'"), std::string::npos) << e.what();
  }
  ema = constructed_ema(0, 50);
  for (Eigen::Index k = 0; k < ema.frame_count(); ++k) ema.drop(4, k);  // tt never sampled
  EXPECT_THROW(register_ema(ema, "head.ema", face, ict_articulography_points()), InputError);
}

TEST(ArticulographyEvaluation, GapsInACoilAreBridged) {
  const RowMajorMatrixXf face = constructed_face(13);
  const MarkerFrames<Millimetres> whole = constructed_ema(5);
  MarkerFrames<Millimetres> gappy = whole;
  for (Eigen::Index k = 400; k < 410; ++k) gappy.drop(3, k);  // 20 ms of the lower lip lost
  const EmaRegistration r = register_ema(gappy, "gappy.ema", face, ict_articulography_points());
  const MeasureCurves a = ema_measure_curves(gappy, r, 100, 1.99);
  const MeasureCurves b = ema_measure_curves(whole, register_ema(whole, "w", face, ict_articulography_points()), 100, 1.99);
  for (std::size_t j = 0; j < a.size(); ++j) EXPECT_NEAR(a.mm[0][j], b.mm[0][j], 0.1) << j;
  EXPECT_THROW(ema_measure_curves(whole, r, 100, 2.5), std::invalid_argument);  // beyond the track
}

// The face side: the points of mean + frames x components, at 60 fps, on the 100 Hz grid.
TEST(ArticulographyEvaluation, FaceCurvesFollowThePcaFramesAndTheTongue) {
  const ArticulographyFacePoints p = ict_articulography_points();
  const RowMajorMatrixXf mean = constructed_face(13);
  RowMajorMatrixXf components = RowMajorMatrixXf::Zero(2, mean.cols());
  components(0, 3 * p.lower_lip + 1) = -0.01f;     // component 1: the lower lip 10 mm down
  components(1, 3 * p.lower_incisor + 1) = -0.005f;  // component 2: the lower incisor 5 mm down
  components(1, 3 * p.chin + 1) = -0.005f;
  components(1, 3 * p.lower_lip + 2) = -0.002f;    // and the lower lip 2 mm back
  const Eigen::Index frames = 120;                  // 2 s at 60 fps
  Eigen::MatrixXf pca(frames, 2), tongue = Eigen::MatrixXf::Zero(frames, 5);
  for (Eigen::Index k = 0; k < frames; ++k) {
    pca(k, 0) = static_cast<float>(k) / 60.0f;  // opens 10 mm per s
    pca(k, 1) = 1.0f;
    tongue(k, 1) = 500;                         // FAP 44: 500 MNS units
  }
  const MeasureCurves m = face_measure_curves(mean, components, pca, tongue, p, 20.48 / 1024, 100, 1.5);
  ASSERT_EQ(m.size(), 151u);
  for (std::size_t j = 0; j < m.size(); ++j) {
    const double t = static_cast<double>(j) / 100;
    EXPECT_NEAR(m.mm[0][j], 12 + 10 * t, 1e-3) << t;          // 8.1 - 8.2 along y
    EXPECT_NEAR(m.mm[1][j], std::hypot(14.0, 1.0), 1e-3) << t;  // incisor tips (y 0 / -14, z 0 / -1)
    EXPECT_NEAR(m.mm[2][j], 60, 1e-3) << t;                     // upper incisor above the chin
    EXPECT_NEAR(m.mm[3][j], 9, 1e-3) << t;                      // 8.2 forward of the incisor
    EXPECT_NEAR(m.mm[4][j], 500 * 20.48 / 1024, 1e-3) << t;     // FAP 44 x MNS
  }
  EXPECT_THROW(face_measure_curves(mean, components, Eigen::MatrixXf::Zero(frames, 3), tongue, p, 20.48 / 1024, 100, 1), std::invalid_argument);
  EXPECT_THROW(face_measure_curves(mean, components, pca, tongue, p, 0, 100, 1), std::invalid_argument);
}

TEST(ArticulographyEvaluation, ThePlotHasAPanelPerMeasureAndACurvePerAnimation) {
  ArticulographyEvaluation e;
  for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m) {
    e.real.mm[m] = {1, 2, 3};
    e.face.mm[m] = {2, 2, 5};
  }
  const std::vector<ArticulographyEvaluation> both{e, e};
  const std::vector<std::string> names{"reference alignment", "own alignment"};
  const LinePlot plot = articulography_plot(both, names, "t");
  ASSERT_EQ(plot.panels.size(), kArticulatoryMeasureCount);
  ASSERT_EQ(plot.panels[0].series.size(), 3u);
  EXPECT_EQ(plot.panels[0].series[0].values, (std::vector<double>{-1, 0, 1}));  // minus the median
  EXPECT_EQ(plot.panels[0].series[1].values, (std::vector<double>{0, 0, 3}));
  EXPECT_EQ(plot.panels[4].y_label, "tongue-tip height (mm, median 0)");
  EXPECT_THROW(articulography_plot(both, std::span(names).first(1), "t"), std::invalid_argument);
}

// Inputs that would give a wrong comparison are refused before any voice is opened.
TEST(ArticulographyEvaluation, InputsThatCannotBeComparedAreRefused) {
  const SampleRate rate{16000};
  const std::vector<TimedPhone> speech{{Phone::SIL, 0, 4000}, {Phone::AA, 4000, 12000}, {Phone::SIL, 12000, 16000}};
  const auto rule_of = [&](const MarkerFrames<Millimetres>& ema, std::span<const TimedPhone> phones) -> std::string {
    try {
      check_articulography_inputs(ema, "head.ema", phones, rate, "head.lab");
    } catch (const InputError& e) {
      return e.rule();
    }
    return "accepted";
  };
  EXPECT_EQ(rule_of(constructed_ema(0), speech), "accepted");
  MarkerFrames<Millimetres> slow = constructed_ema(0, 50);  // 50 frames at 25 Hz: 2 s
  slow.frame_rate_hz = 25;
  EXPECT_EQ(rule_of(slow, speech), "ema-rate");
  MarkerFrames<Millimetres> late = constructed_ema(0);
  late.first_frame = 100;  // starts at 0.2 s: the grid from 0 would hold it flat
  EXPECT_EQ(rule_of(late, speech), "articulography-span");
  MarkerFrames<Millimetres> upside_down = constructed_ema(0);
  for (Eigen::Index k = 0; k < upside_down.frame_count(); ++k)
    for (Eigen::Index m = 0; m < upside_down.marker_count(); ++m)
      upside_down.positions(3 * m + 1, k) = -upside_down.positions(3 * m + 1, k);
  EXPECT_EQ(rule_of(upside_down, speech), "ema-coils");
  const std::vector<TimedPhone> silent{{Phone::SIL, 0, 16000}};
  EXPECT_EQ(rule_of(constructed_ema(0), silent), "articulography-span");
}

}  // namespace
}  // namespace fapcast
