#include "fapcast/eval/articulography_evaluation.hpp"

#include "fapcast/codec/fapu_values.hpp"
#include "fapcast/codec/feature_point.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/face/marker_map.hpp"
#include "fapcast/math/sample_statistics.hpp"
#include "fapcast/math/zero_phase_lowpass.hpp"
#include "fapcast/talker/articulation.hpp"
#include "fapcast/talker/coarticulation.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace fapcast {
namespace {

constexpr std::array<std::string_view, kArticulatoryMeasureCount> kNames{
    "lip aperture", "jaw opening", "jaw opening (chin 2.1)", "lower-lip protrusion", "tongue-tip height"};
constexpr std::array<std::string_view, kArticulatoryMeasureCount> kKeys{
    "lip_aperture", "jaw_opening", "jaw_opening_chin", "lower_lip_protrusion", "tongue_tip_height"};

// The alignment's speech may end this long after the EMA's last frame (rounding of the labels).
constexpr double kSpanToleranceS = 0.02;

// (y, z) of vertex v of a 1 x 3N mesh, millimetres.
std::array<double, 2> sagittal_mm(const Eigen::Ref<const RowMajorMatrixXf>& mesh_m, std::int32_t v) {
  if (v < 0 || 3 * static_cast<Eigen::Index>(v) + 2 >= mesh_m.cols())
    throw std::invalid_argument("articulography: vertex " + std::to_string(v) + " is not on a mesh of " +
                                std::to_string(mesh_m.cols() / 3) + " vertices");
  return {1000.0 * mesh_m(0, 3 * v + 1), 1000.0 * mesh_m(0, 3 * v + 2)};
}

// Linear samples of (times, values) at j / rate_out for j = 0 .. floor(end_s x rate_out); held
// before the first and after the last time.
std::vector<double> resample(std::span<const double> times_s, std::span<const double> values, double rate_out,
                             double end_s) {
  const auto n = static_cast<std::size_t>(std::floor(end_s * rate_out + 1e-9)) + 1;
  std::vector<double> out;
  out.reserve(n);
  std::size_t i = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double t = static_cast<double>(j) / rate_out;
    while (i + 1 < times_s.size() && times_s[i + 1] <= t) ++i;
    if (t <= times_s.front()) {
      out.push_back(values.front());
    } else if (i + 1 >= times_s.size()) {
      out.push_back(values.back());
    } else {
      const double w = (t - times_s[i]) / (times_s[i + 1] - times_s[i]);
      out.push_back(values[i] + w * (values[i + 1] - values[i]));
    }
  }
  return out;
}

// Coil `label`'s x and y per frame with its gaps (NaN) bridged linearly and its ends held; empty
// when the file has no such coil or no sample of it.
std::array<std::vector<double>, 2> coil_track(const MarkerFrames<Millimetres>& ema, std::string_view label) {
  const auto m = ema.find(label);
  if (!m) return {};
  const Eigen::Index n = ema.frame_count();
  std::array<std::vector<double>, 2> xy;
  std::vector<Eigen::Index> present;
  for (Eigen::Index k = 0; k < n; ++k)
    if (ema.present(*m, k)) present.push_back(k);
  if (present.empty()) return {};
  for (int c = 0; c < 2; ++c) {
    auto& v = xy[static_cast<std::size_t>(c)];
    v.resize(static_cast<std::size_t>(n));
    const auto at = [&](Eigen::Index k) { return ema.positions(3 * *m + c, k); };
    std::size_t p = 0;  // present[p] <= k < present[p + 1] inside the span
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto out = static_cast<std::size_t>(k);
      if (k <= present.front()) {
        v[out] = at(present.front());
      } else if (k >= present.back()) {
        v[out] = at(present.back());
      } else {
        while (present[p + 1] <= k) ++p;
        const Eigen::Index a = present[p], b = present[p + 1];
        const double w = static_cast<double>(k - a) / static_cast<double>(b - a);
        v[out] = at(a) + w * (at(b) - at(a));
      }
    }
  }
  return xy;
}

// coil_track of a coil the evaluation needs; InputError "ema-coils" when there is none.
std::array<std::vector<double>, 2> used_coil(const MarkerFrames<Millimetres>& ema, std::string_view label,
                                             const std::string& source) {
  auto xy = coil_track(ema, label);
  if (xy[0].empty())
    throw InputError({source, std::nullopt, std::nullopt}, "ema-coils",
                     "no samples of coil '" + std::string(label) +
                         "': the evaluation needs the coils ui li ul ll tt bn (spec/articulography.md)");
  return xy;
}

double mean(std::span<const double> x) {
  double s = 0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

double median(std::span<const double> x) { return percentile(x, 50); }

// A best lag on the edge of the searched window is no lag found: the curves do not line up.
bool at_window_edge(const TrajectoryAgreement& a, const ArticulographySettings& settings) {
  return std::abs(a.best_lag_s) > settings.max_lag_s - settings.lag_step_s / 2;
}

}  // namespace

std::string_view articulatory_measure_name(ArticulatoryMeasure m) { return kNames.at(static_cast<std::size_t>(m)); }
std::string_view articulatory_measure_key(ArticulatoryMeasure m) { return kKeys.at(static_cast<std::size_t>(m)); }

ArticulographyFacePoints ict_articulography_points() {
  const auto fp = [](std::string_view label) { return marker_sites()[marker_row(label)].vertex; };
  return {.upper_lip = fp("8.1"),
          .lower_lip = fp("8.2"),
          .chin = fp("2.1"),
          .upper_incisor = 18075,
          .lower_incisor = 20271,
          .nose_dorsum = {978, 4527, 4942, 4857}};
}

double face_nose_angle_rad(const Eigen::Ref<const RowMajorMatrixXf>& mesh_m, const ArticulographyFacePoints& points,
                           double distance_mm) {
  const auto ui = sagittal_mm(mesh_m, points.upper_incisor);
  std::array<std::array<double, 3>, 4> chain{};  // (up, forward, distance) from the incisor, root first
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const auto p = sagittal_mm(mesh_m, points.nose_dorsum[k]);
    const double up = p[0] - ui[0], fwd = p[1] - ui[1];
    chain[k] = {up, fwd, std::hypot(up, fwd)};
  }
  std::array<double, 2> at{chain.front()[0], chain.front()[1]};  // beyond the root: the root
  if (distance_mm <= chain.back()[2]) at = {chain.back()[0], chain.back()[1]};
  for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
    const auto& a = chain[k];
    const auto& b = chain[k + 1];
    if (distance_mm <= a[2] && distance_mm >= b[2] && a[2] > b[2]) {
      const double s = (a[2] - distance_mm) / (a[2] - b[2]);
      at = {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])};
      break;
    }
  }
  return std::atan2(at[1], at[0]);
}

namespace {

// The part of the registration the coils alone decide (origin, forward, the nose's distance and
// angle); the face's angle is added by register_ema. Throws InputError for coils that give no frame.
EmaRegistration register_coils(const MarkerFrames<Millimetres>& ema, const std::string& source) {
  std::array<std::array<double, 2>, kEmaCoilsUsed.size()> means{};
  for (std::size_t c = 0; c < kEmaCoilsUsed.size(); ++c) {
    const auto xy = used_coil(ema, kEmaCoilsUsed[c], source);
    means[c] = {mean(xy[0]), mean(xy[1])};
  }
  const auto& ui = means[0];
  const auto& ul = means[2];
  const auto& bn = means[5];
  EmaRegistration r;
  r.origin_x_mm = ui[0];
  r.origin_y_mm = ui[1];
  if (std::abs(ul[0] - ui[0]) < 1)
    throw InputError({source, std::nullopt, std::nullopt}, "ema-coils",
                     "the upper-lip coil is not in front of the upper-incisor coil (mean x " + fixed(ul[0], 2) +
                         " and " + fixed(ui[0], 2) + " mm): no forward direction");
  r.forward_sign = ul[0] > ui[0] ? 1.0 : -1.0;
  const double f = r.forward_sign * (bn[0] - ui[0]), u = bn[1] - ui[1];
  r.nose_distance_mm = std::hypot(f, u);
  if (!(r.nose_distance_mm > 10))
    throw InputError({source, std::nullopt, std::nullopt}, "ema-coils",
                     "the nose-bridge coil lies " + fixed(r.nose_distance_mm, 1) +
                         " mm from the upper incisor: too close to give the head's pitch");
  // The frame's y must point up: a rotation cannot undo a y-down track (forward would flip too).
  if (!(u > 0))
    throw InputError({source, std::nullopt, std::nullopt}, "ema-coils",
                     "the nose-bridge coil lies " + fixed(-u, 1) +
                         " mm below the upper incisor: the file's y axis must point up (MOCHA's does)");
  r.coil_angle_rad = std::atan2(f, u);
  return r;
}

}  // namespace

EmaRegistration register_ema(const MarkerFrames<Millimetres>& ema, const std::string& source,
                             const Eigen::Ref<const RowMajorMatrixXf>& mesh_m, const ArticulographyFacePoints& points) {
  EmaRegistration r = register_coils(ema, source);
  r.face_angle_rad = face_nose_angle_rad(mesh_m, points, r.nose_distance_mm);
  r.rotation_rad = r.face_angle_rad - r.coil_angle_rad;
  return r;
}

MeasureCurves ema_measure_curves(const MarkerFrames<Millimetres>& ema, const EmaRegistration& reg, double rate_hz,
                                 double end_s, double lowpass_hz) {
  const Eigen::Index n = ema.frame_count();
  if (n < 3) throw std::invalid_argument("ema_measure_curves: fewer than 3 frames");
  std::vector<double> times(static_cast<std::size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k)
    times[static_cast<std::size_t>(k)] = static_cast<double>(ema.first_frame + k) / ema.frame_rate_hz;
  if (!(end_s >= times.front()) || end_s > times.back() + 1e-9)
    throw std::invalid_argument("ema_measure_curves: end beyond the track");
  const double c = std::cos(reg.rotation_rad), s = std::sin(reg.rotation_rad);
  // (forward, up) of each used coil after low-pass and rotation: angle a from up goes to a + rotation.
  std::array<std::array<std::vector<double>, 2>, kEmaCoilsUsed.size()> fu;
  for (std::size_t coil = 0; coil < kEmaCoilsUsed.size(); ++coil) {
    auto xy = coil_track(ema, kEmaCoilsUsed[coil]);
    if (xy[0].empty()) throw std::invalid_argument("ema_measure_curves: no coil " + std::string(kEmaCoilsUsed[coil]));
    for (auto& x : xy[0]) x = reg.forward_sign * (x - reg.origin_x_mm);
    for (auto& y : xy[1]) y -= reg.origin_y_mm;
    auto f = zero_phase_lowpass(xy[0], ema.frame_rate_hz, lowpass_hz);
    auto u = zero_phase_lowpass(xy[1], ema.frame_rate_hz, lowpass_hz);
    for (std::size_t k = 0; k < f.size(); ++k) {
      const double ff = c * f[k] + s * u[k], uu = -s * f[k] + c * u[k];
      f[k] = ff;
      u[k] = uu;
    }
    fu[coil] = {std::move(f), std::move(u)};
  }
  const auto& ui = fu[0];
  const auto& li = fu[1];
  const auto& ul = fu[2];
  const auto& ll = fu[3];
  const auto& tt = fu[4];
  std::array<std::vector<double>, kArticulatoryMeasureCount> raw;
  for (auto& r : raw) r.resize(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    raw[0][k] = ul[1][k] - ll[1][k];
    raw[1][k] = std::hypot(ui[0][k] - li[0][k], ui[1][k] - li[1][k]);
    raw[2][k] = ui[1][k] - li[1][k];
    raw[3][k] = ll[0][k];
    raw[4][k] = tt[1][k];
  }
  MeasureCurves out;
  out.rate_hz = rate_hz;
  for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m) out.mm[m] = resample(times, raw[m], rate_hz, end_s);
  return out;
}

MeasureCurves face_measure_curves(const Eigen::Ref<const RowMajorMatrixXf>& mean_m,
                                  const Eigen::Ref<const RowMajorMatrixXf>& components_m, const Eigen::MatrixXf& pca_frames,
                                  const Eigen::MatrixXf& tongue, const ArticulographyFacePoints& points, double mns_mm,
                                  double rate_hz, double end_s) {
  const Eigen::Index frames = pca_frames.rows();
  if (components_m.cols() != mean_m.cols() || pca_frames.cols() != components_m.rows() || tongue.rows() != frames ||
      tongue.cols() < 2 || frames < 1)
    throw std::invalid_argument("face_measure_curves: mean, components, PCA frames and tongue disagree in shape");
  // The points' (y, z) per frame in mm: mean + frame . components at the vertex.
  const std::array<std::int32_t, 5> vertices{points.upper_lip, points.lower_lip, points.chin, points.upper_incisor,
                                             points.lower_incisor};
  std::array<std::array<std::vector<double>, 2>, 5> yz;
  for (std::size_t p = 0; p < vertices.size(); ++p) {
    sagittal_mm(mean_m, vertices[p]);  // checks the vertex
    for (int a = 0; a < 2; ++a) {
      const Eigen::Index col = 3 * static_cast<Eigen::Index>(vertices[p]) + 1 + a;
      const Eigen::VectorXf v = (pca_frames * components_m.col(col)).array() + mean_m(0, col);
      auto& out = yz[p][static_cast<std::size_t>(a)];
      out.resize(static_cast<std::size_t>(frames));
      for (Eigen::Index k = 0; k < frames; ++k) out[static_cast<std::size_t>(k)] = 1000.0 * v(k);
    }
  }
  if (!(mns_mm > 0)) throw std::invalid_argument("face_measure_curves: the face's mouth-nose separation is not positive");
  std::vector<double> times(static_cast<std::size_t>(frames));
  std::array<std::vector<double>, kArticulatoryMeasureCount> raw;
  for (auto& r : raw) r.resize(times.size());
  const auto& [ul, ll, chin, ui, li] = yz;
  for (std::size_t k = 0; k < times.size(); ++k) {
    times[k] = static_cast<double>(k) / static_cast<double>(kVoiceFramesPerSecond);
    raw[0][k] = ul[0][k] - ll[0][k];
    raw[1][k] = std::hypot(ui[0][k] - li[0][k], ui[1][k] - li[1][k]);
    raw[2][k] = ui[0][k] - chin[0][k];
    raw[3][k] = ll[1][k] - ui[1][k];
    raw[4][k] = static_cast<double>(tongue(static_cast<Eigen::Index>(k), 1)) * mns_mm;
  }
  MeasureCurves out;
  out.rate_hz = rate_hz;
  for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m) out.mm[m] = resample(times, raw[m], rate_hz, end_s);
  return out;
}

void check_articulography_inputs(const MarkerFrames<Millimetres>& ema, const std::string& ema_source,
                                 std::span<const TimedPhone> phones, SampleRate sample_rate,
                                 const std::string& phones_source) {
  const Eigen::Index frames = ema.frame_count();
  if (frames < 3)
    throw InputError({ema_source, std::nullopt, std::nullopt}, "ema-too-short",
                     std::to_string(frames) + " frames: the evaluation needs at least 3");
  const double first_s = static_cast<double>(ema.first_frame) / ema.frame_rate_hz;
  const double end_s = static_cast<double>(ema.first_frame + frames - 1) / ema.frame_rate_hz;
  // The comparison grid runs from 0 (the speech's start): an EMA starting later would be held flat there.
  if (first_s < 0 || first_s > kSpanToleranceS)
    throw InputError({ema_source, std::nullopt, std::nullopt}, "articulography-span",
                     "the EMA starts at " + fixed(first_s, 3) + " s: it must start with the speech, at 0");
  // 100 Hz: the comparison grid's rate, and over twice the 15 Hz low-pass.
  if (!(ema.frame_rate_hz >= 100))
    throw InputError({ema_source, std::nullopt, std::nullopt}, "ema-rate",
                     "the EMA's rate " + fixed(ema.frame_rate_hz, 1) +
                         " Hz is below 100 Hz, the rate the evaluation compares at");
  (void)register_coils(ema, ema_source);  // its refusals before any voice is opened
  const auto seconds = [&](std::int64_t sample) { return static_cast<double>(sample) / static_cast<double>(sample_rate.hz); };
  std::size_t spoken = 0;
  for (const TimedPhone& p : phones) {
    if (p.phone == Phone::SIL) continue;
    ++spoken;
    if (seconds(p.end_sample) > end_s + kSpanToleranceS || seconds(p.start_sample) < first_s - kSpanToleranceS)
      throw InputError({phones_source, std::nullopt, std::nullopt}, "articulography-span",
                       "a phone spoken from " + fixed(seconds(p.start_sample), 3) + " to " + fixed(seconds(p.end_sample), 3) +
                           " s lies outside the EMA " + ema_source + " (" + fixed(first_s, 3) + " to " + fixed(end_s, 3) +
                           " s): the articulography must cover the speech");
  }
  if (spoken == 0)
    throw InputError({phones_source, std::nullopt, std::nullopt}, "articulography-span",
                     "no phone is spoken (only silences and noises): nothing to compare with the EMA");
}

namespace {

// What both animations share: the registration on the voice's mean face `voice_mean_m` (so that
// the real curves are the same whatever animates the face), the real curves, and the face's curves
// from frames of `components_m` about `mean_m`.
ArticulographyEvaluation compare_with_face(const MarkerFrames<Millimetres>& ema, const std::string& ema_source,
                                           const Eigen::Ref<const RowMajorMatrixXf>& voice_mean_m,
                                           const Eigen::Ref<const RowMajorMatrixXf>& mean_m,
                                           const Eigen::Ref<const RowMajorMatrixXf>& components_m,
                                           const Eigen::MatrixXf& frames, const SynthesizedTrack& track,
                                           double mns_mm, const std::string& phones_source,
                                           const ArticulographySettings& settings) {
  ArticulographyEvaluation e;
  e.settings = settings;
  e.ema_rate_hz = ema.frame_rate_hz;
  e.ema_frames = ema.frame_count();
  e.end_s = static_cast<double>(ema.first_frame + e.ema_frames - 1) / ema.frame_rate_hz;
  const ArticulographyFacePoints points = ict_articulography_points();
  if (voice_mean_m.cols() <= 3 * static_cast<Eigen::Index>(points.lower_incisor) + 2)
    throw InputError({phones_source, std::nullopt, std::nullopt}, "articulography-mesh",
                     "the voice's face has " + std::to_string(voice_mean_m.cols() / 3) +
                         " vertices: the face points are ICT-FaceKit vertices (an ICT-topology voice is needed)");
  e.registration = register_ema(ema, ema_source, voice_mean_m, points);
  e.registration.rotation_rad += settings.extra_rotation_rad;
  e.real = ema_measure_curves(ema, e.registration, settings.rate_hz, e.end_s, settings.lowpass_hz);
  if (frames.rows() < 1)
    throw InputError({phones_source, std::nullopt, std::nullopt}, "articulography-span", "no frames were synthesised");
  e.phones = track.timeline.phones.size();
  e.units = track.search.units.size();
  e.face = face_measure_curves(mean_m, components_m, frames, track.tongue, points, mns_mm, settings.rate_hz, e.end_s);
  for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m)
    e.agreement[m] = trajectory_agreement(e.real.mm[m], e.face.mm[m], settings.rate_hz, settings.max_lag_s,
                                          settings.lag_step_s);
  return e;
}

// The voice's MNS FAPU in mm, measured on its neutral feature points as a renderer measures it
// (codec's FAPU rule): the tongue FAPs are in it.
double neutral_mns_mm(const Voice& voice) {
  FeaturePointPositions neutral_m;
  for (const VoiceFeaturePoint& p : voice.feature_points())
    if (const auto fp = parse_feature_point(p.label)) neutral_m[*fp] = p.neutral_m;
  return 1000 * measure_fapu(neutral_m).mns;
}

// Each phone's share of 1 - r (PhoneLoss): the grid cut at the sample nearest each phone's start.
std::vector<PhoneLoss> loss_by_phone(const ArticulographyEvaluation& e, std::span<const TimedPhone> phones,
                                     SampleRate sample_rate) {
  const std::size_t n = e.real.size();
  const double rate_hz = e.real.rate_hz;
  std::vector<SampleSpan> spans;
  std::size_t begin = 0;
  for (std::size_t i = 0; i < phones.size(); ++i) {
    std::size_t end = n;
    if (i + 1 < phones.size()) {
      const double next_start_s = static_cast<double>(phones[i + 1].start_sample) / static_cast<double>(sample_rate.hz);
      end = std::clamp(static_cast<std::size_t>(std::max(0.0, std::round(next_start_s * rate_hz))), begin, n);
    }
    spans.push_back({begin, end});
    begin = end;
  }
  std::vector<PhoneLoss> out(phones.size());
  for (std::size_t i = 0; i < phones.size(); ++i) {
    out[i].phone = phones[i].phone;
    out[i].start_s = static_cast<double>(spans[i].begin) / rate_hz;
    out[i].end_s = static_cast<double>(spans[i].end) / rate_hz;
  }
  for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m) {
    const std::vector<double> loss = correlation_loss_by_span(e.real.mm[m], e.face.mm[m], spans);
    for (std::size_t i = 0; i < phones.size(); ++i) out[i].loss[m] = loss[i];
  }
  return out;
}

}  // namespace

ArticulographyEvaluation evaluate_articulography(const MarkerFrames<Millimetres>& ema, const std::string& ema_source,
                                                 const Voice& voice, std::span<const TimedPhone> phones,
                                                 SampleRate sample_rate, std::int64_t audio_samples,
                                                 const SynthesisOptions& options, const std::string& phones_source,
                                                 const ArticulographySettings& settings) {
  check_articulography_inputs(ema, ema_source, phones, sample_rate, phones_source);
  const SynthesizedTrack track = synthesize(voice, phones, sample_rate, audio_samples, options, phones_source);
  ArticulographyEvaluation e = compare_with_face(ema, ema_source, voice.pca_mean(), voice.pca_mean(), voice.pca_components(),
                                                 track.pca_frames, track, neutral_mns_mm(voice), phones_source, settings);
  e.unit_sources = unit_sources(voice.graph(), voice.state_phones(), track.search);
  e.asked = track.timeline.phone_of;
  e.loss_by_phone = loss_by_phone(e, phones, sample_rate);
  return e;
}

ArticulographyEvaluation evaluate_talker_articulography(const MarkerFrames<Millimetres>& ema,
                                                        const std::string& ema_source, const Voice& voice,
                                                        std::span<const TimedPhone> phones, SampleRate sample_rate,
                                                        std::int64_t audio_samples, const SynthesisOptions& options,
                                                        const std::string& phones_source,
                                                        const ArticulographySettings& settings) {
  check_articulography_inputs(ema, ema_source, phones, sample_rate, phones_source);
  // The tongue is the parametric tongue of the same phones (the talker's tongue channels drive no
  // face shape), so that only the face differs from the voice's animation.
  SynthesisOptions tongue_only = options;  // no unit of this search is shown: no jaw to weigh or level
  tongue_only.search.jaw_weight = 0.0;
  tongue_only.jaw_level = 0.0;
  const SynthesizedTrack track = synthesize(voice.graph(), voice.frame_coefficients(), phones, sample_rate,
                                            audio_samples, tongue_only, phones_source);
  const FaceModel& face = ict_face_model();
  const Eigen::MatrixXf weights =
      expression_weights(coarticulate({sample_rate, {phones.begin(), phones.end()}}), ShapeMapper(face));
  // The shapes the talker uses, dense (metres), about the generic neutral: the face the default
  // voice is retargeted to.
  std::vector<Eigen::Index> used;
  for (Eigen::Index s = 0; s < weights.rows(); ++s)
    if (weights.row(s).cwiseAbs().maxCoeff() > 0) used.push_back(s);
  const Eigen::Index n = face.neutral_cm.cols();
  RowMajorMatrixXf mean_m(1, 3 * n);
  for (Eigen::Index v = 0; v < n; ++v)
    for (int a = 0; a < 3; ++a) mean_m(0, 3 * v + a) = face.neutral_cm(a, v) / 100.0f;
  RowMajorMatrixXf components_m = RowMajorMatrixXf::Zero(static_cast<Eigen::Index>(used.size()), 3 * n);
  // On the voice's frames of the same span (synthesize runs to the audio's end; the talker to the
  // last phone's): the talker's last frame held.
  const Eigen::Index frame_count = track.pca_frames.rows();
  Eigen::MatrixXf frames(frame_count, static_cast<Eigen::Index>(used.size()));
  for (std::size_t i = 0; i < used.size(); ++i) {
    const SparseDelta& d = face.expressions[static_cast<std::size_t>(used[i])];
    for (std::size_t j = 0; j < d.vertices.size(); ++j)
      for (int a = 0; a < 3; ++a)
        components_m(static_cast<Eigen::Index>(i), 3 * d.vertices[j] + a) =
            d.offsets_cm(a, static_cast<Eigen::Index>(j)) / 100.0f;
    for (Eigen::Index k = 0; k < frame_count; ++k)
      frames(k, static_cast<Eigen::Index>(i)) = weights(used[i], std::min(k, weights.cols() - 1));
  }
  ArticulographyEvaluation e = compare_with_face(ema, ema_source, voice.pca_mean(), mean_m, components_m, frames, track,
                                                 neutral_mns_mm(voice), phones_source, settings);
  e.units = 0;  // no units: the talker's tracks are continuous
  e.loss_by_phone = loss_by_phone(e, phones, sample_rate);
  return e;
}

namespace {

// "W AH Z": the target phones a unit stands for.
std::string asked_phones(const ArticulographyEvaluation& e, const UnitSource& s) {
  std::string out;
  for (std::size_t t = s.unit.first_target; t < s.unit.first_target + s.unit.length && t < e.asked.size(); ++t) {
    if (!out.empty()) out += ' ';
    out += arpabet(e.asked[t]);
  }
  return out;
}

}  // namespace

std::string articulography_table(const ArticulographyEvaluation& e, const std::string& title) {
  std::ostringstream out;
  out << title << "\n";
  out << "| measure | range real mm | range ours mm | ours / real | r (zero lag) | best lag ms (+ = ours behind) | r at best lag |\n";
  out << "|---|---|---|---|---|---|---|\n";
  for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m) {
    const TrajectoryAgreement& a = e.agreement[m];
    out << "| " << kNames[m] << " | " << fixed(a.reference_range, 2) << " | " << fixed(a.compared_range, 2) << " | "
        << fixed(a.range_ratio, 2) << " | " << fixed(a.r_zero_lag, 2) << " | " << fixed(1000 * a.best_lag_s, 0)
        << (at_window_edge(a, e.settings) ? " (window edge)" : "") << " | " << fixed(a.r_best_lag, 2) << " |\n";
  }
  const EmaRegistration& r = e.registration;
  out << "\nEMA " << e.ema_frames << " frames at " << fixed(e.ema_rate_hz, 1) << " Hz, compared on 0 to " << fixed(e.end_s, 3)
      << " s at " << fixed(e.settings.rate_hz, 0) << " Hz; coils low-passed at " << fixed(e.settings.lowpass_hz, 0)
      << " Hz (zero phase); registration: origin the mean upper incisor, ui->bn " << fixed(r.nose_distance_mm, 1)
      << " mm at " << fixed(degrees(r.coil_angle_rad), 1) << " deg (forward of up) turned by "
      << fixed(degrees(r.rotation_rad), 1) << " deg to the face's nose-dorsum angle " << fixed(degrees(r.face_angle_rad), 1)
      << " deg; " << e.phones << " phones in " << e.units << " units\n";
  if (!e.unit_sources.empty()) {
    out << "\nunits (phones asked <- take: its phones, the unit's in brackets):";
    for (std::size_t u = 0; u < e.unit_sources.size(); ++u) {
      const UnitSource& s = e.unit_sources[u];
      out << (u == 0 ? " " : "; ") << asked_phones(e, s) << " <- " << s.take << ": " << describe_take(s);
    }
    out << "\n";
  }
  return out.str();
}

std::string articulography_loss_table(const ArticulographyEvaluation& e, const std::string& title) {
  constexpr std::array kShown{ArticulatoryMeasure::lip_aperture, ArticulatoryMeasure::jaw_opening,
                              ArticulatoryMeasure::lower_lip_protrusion};
  std::ostringstream out;
  out << title << "\n| phone | from s | to s |";
  for (const ArticulatoryMeasure m : kShown) out << " " << articulatory_measure_name(m) << " |";
  out << "\n|---|---|---|---|---|---|\n";
  for (const PhoneLoss& p : e.loss_by_phone) {
    out << "| " << arpabet(p.phone) << " | " << fixed(p.start_s, 2) << " | " << fixed(p.end_s, 2) << " |";
    for (const ArticulatoryMeasure m : kShown) out << " " << fixed(p.loss[static_cast<std::size_t>(m)], 3) << " |";
    out << "\n";
  }
  out << "| whole take (1 - r) | 0.00 | " << fixed(static_cast<double>(e.real.size()) / e.real.rate_hz, 2) << " |";
  for (const ArticulatoryMeasure m : kShown)
    out << " " << fixed(1 - e.agreement[static_cast<std::size_t>(m)].r_zero_lag, 3) << " |";
  out << "\n";
  return out.str();
}

std::string alignment_effect_table(const ArticulographyEvaluation& reference, const ArticulographyEvaluation& own) {
  std::ostringstream out;
  const auto change = [](double own_v, double ref_v) {
    return ref_v != 0 ? fixed(100 * (own_v - ref_v) / std::abs(ref_v), 0) + " %" : std::string("-");
  };
  out << "| measure | ours / real: reference alignment | own alignment | change | r: reference alignment | own "
         "alignment | change |\n";
  out << "|---|---|---|---|---|---|---|\n";
  for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m) {
    const TrajectoryAgreement& a = reference.agreement[m];
    const TrajectoryAgreement& b = own.agreement[m];
    out << "| " << kNames[m] << " | " << fixed(a.range_ratio, 2) << " | " << fixed(b.range_ratio, 2) << " | "
        << change(b.range_ratio, a.range_ratio) << " | " << fixed(a.r_zero_lag, 2) << " | " << fixed(b.r_zero_lag, 2)
        << " | " << (b.r_zero_lag >= a.r_zero_lag ? "+" : "") << fixed(b.r_zero_lag - a.r_zero_lag, 2) << " ("
        << change(b.r_zero_lag, a.r_zero_lag) << ") |\n";
  }
  return out.str();
}

nlohmann::json articulography_json(const ArticulographyEvaluation& e) {
  const EmaRegistration& r = e.registration;
  nlohmann::json j;
  j["ema"] = {{"frames", e.ema_frames}, {"rate_hz", e.ema_rate_hz}, {"end_s", e.end_s}};
  j["settings"] = {{"rate_hz", e.settings.rate_hz},
                   {"lowpass_hz", e.settings.lowpass_hz},
                   {"max_lag_s", e.settings.max_lag_s},
                   {"lag_step_s", e.settings.lag_step_s}};
  j["registration"] = {{"origin_mm", {r.origin_x_mm, r.origin_y_mm}},
                       {"forward_sign", r.forward_sign},
                       {"nose_distance_mm", r.nose_distance_mm},
                       {"coil_angle_deg", degrees(r.coil_angle_rad)},
                       {"face_angle_deg", degrees(r.face_angle_rad)},
                       {"rotation_deg", degrees(r.rotation_rad)}};
  j["synthesis"] = {{"phones", e.phones}, {"units", e.units}};
  if (!e.unit_sources.empty()) {
    nlohmann::json units = nlohmann::json::array();
    for (const UnitSource& s : e.unit_sources)
      units.push_back({{"first_phone", s.unit.first_target},
                       {"phones", asked_phones(e, s)},
                       {"take", s.take},
                       {"take_phones", describe_take(s)}});
    j["synthesis"]["unit_sources"] = std::move(units);
  }
  nlohmann::json losses = nlohmann::json::array();
  for (const PhoneLoss& p : e.loss_by_phone) {
    nlohmann::json one = {{"phone", arpabet(p.phone)}, {"start_s", p.start_s}, {"end_s", p.end_s}};
    for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m) one["loss"][std::string(kKeys[m])] = p.loss[m];
    losses.push_back(std::move(one));
  }
  j["loss_by_phone"] = std::move(losses);
  j["curves"]["rate_hz"] = e.real.rate_hz;
  for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m) {
    const TrajectoryAgreement& a = e.agreement[m];
    j["measures"][std::string(kKeys[m])] = {{"range_real_mm", a.reference_range},
                                            {"range_ours_mm", a.compared_range},
                                            {"range_ratio", a.range_ratio},
                                            {"r_zero_lag", a.r_zero_lag},
                                            {"best_lag_ms", 1000 * a.best_lag_s},
                                            {"r_best_lag", a.r_best_lag},
                                            {"best_lag_at_window_edge", at_window_edge(a, e.settings)}};
    j["curves"]["real_mm"][std::string(kKeys[m])] = e.real.mm[m];
    j["curves"]["ours_mm"][std::string(kKeys[m])] = e.face.mm[m];
  }
  return j;
}

LinePlot articulography_plot(std::span<const ArticulographyEvaluation> evaluations, std::span<const std::string> names,
                             const std::string& title) {
  if (evaluations.empty() || names.size() != evaluations.size())
    throw std::invalid_argument("articulography_plot: one name per evaluation");
  LinePlot plot;
  plot.title = title;
  plot.x_label = "time (s)";
  plot.x_step = 1.0 / evaluations.front().real.rate_hz;
  const auto centred = [](std::vector<double> v) {
    const double m = median(v);
    for (double& x : v) x -= m;
    return v;
  };
  for (std::size_t m = 0; m < kArticulatoryMeasureCount; ++m) {
    PlotPanel panel;
    panel.y_label = std::string(kNames[m]) + " (mm, median 0)";
    panel.series.push_back({"real (EMA)", centred(evaluations.front().real.mm[m])});
    for (std::size_t i = 0; i < evaluations.size(); ++i) panel.series.push_back({names[i], centred(evaluations[i].face.mm[m])});
    plot.panels.push_back(std::move(panel));
  }
  return plot;
}

}  // namespace fapcast
