#pragma once
// A synthesised face against real articulography (spec/articulography.md, "Evaluation against
// articulography"): an utterance is animated from its phones on a voice, and lip aperture, jaw
// opening, lower-lip protrusion and tongue-tip height are measured on the face's ICT vertices and
// on the EMA coils after a stated registration, low-passed (the coils), resampled to one 100 Hz
// grid from 0 to the EMA's end and compared (trajectory_agreement.hpp).
#include "fapcast/core/eigen_types.hpp"
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/corpus/marker_frames.hpp"
#include "fapcast/eval/svg_plot.hpp"
#include "fapcast/eval/trajectory_agreement.hpp"
#include "fapcast/phonetics/timed_phone.hpp"
#include "fapcast/select/unit_sources.hpp"
#include "fapcast/synthesis/synthesis.hpp"
#include "fapcast/voice/voice.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

enum class ArticulatoryMeasure : std::uint8_t {
  lip_aperture,          // real (ul - ll) . up;          face (8.1 - 8.2) . y
  jaw_opening,           // real |ui - li| (no rotation); face |upper - lower incisor tip|, midsagittal
  jaw_opening_chin,      // real (ui - li) . up;          face -(2.1 . y): the chin, as issue 15 measured it
  lower_lip_protrusion,  // real ll . forward;            face 8.2 . z
  tongue_tip_height,     // real tt . up;                 face FAP 44 (raise_tongue_tip) x MNS
};
inline constexpr std::size_t kArticulatoryMeasureCount = 5;
// "lip aperture", "jaw opening", "jaw opening (chin 2.1)", "lower-lip protrusion", "tongue-tip height".
std::string_view articulatory_measure_name(ArticulatoryMeasure m);
// "lip_aperture", "jaw_opening", "jaw_opening_chin", "lower_lip_protrusion", "tongue_tip_height".
std::string_view articulatory_measure_key(ArticulatoryMeasure m);

// The MOCHA coils the measures need (corpus/ema.hpp's labels).
inline constexpr std::array<std::string_view, 6> kEmaCoilsUsed{"ui", "li", "ul", "ll", "tt", "bn"};

// The ICT-FaceKit vertices the face side reads (spec/articulography.md, "Face points").
struct ArticulographyFacePoints {
  std::int32_t upper_lip;      // FP 8.1 (face/marker_map)
  std::int32_t lower_lip;      // FP 8.2
  std::int32_t chin;           // FP 2.1
  std::int32_t upper_incisor;  // tip of the upper central incisors: moved by no ICT expression shape
  std::int32_t lower_incisor;  // tip of the lower central incisors: moved by jawOpen
  std::array<std::int32_t, 4> nose_dorsum;  // ICT landmarks 27..30, nose root to tip
};
ArticulographyFacePoints ict_articulography_points();

// How the coils' frame is put onto the face's (face: origin the upper incisor tip, up = +y,
// forward = +z). The coils are taken relative to the mean upper-incisor coil; "forward" is the
// file's x direction in which the upper lip lies from the upper incisor; then one rotation in
// the midsagittal plane makes the vector ui -> bn (nose-bridge coil, means) meet "up" at the
// angle at which, on the face, the nose-dorsum point at the same distance from the upper incisor
// meets +y.
struct EmaRegistration {
  double origin_x_mm = 0, origin_y_mm = 0;  // mean ui in the file's frame
  double forward_sign = -1;                 // the file's x times this is "forward" (MOCHA: x points back)
  double nose_distance_mm = 0;              // |ui -> bn|
  double coil_angle_rad = 0;                // ui -> bn from "up" before rotation, + = forward
  double face_angle_rad = 0;                // the face's nose point at that distance, + = forward
  double rotation_rad = 0;                  // face_angle - coil_angle: applied to every coil
};

// The angle from +y (+ = towards +z) of the point on the nose-dorsum polyline at `distance_mm`
// from the upper incisor, on a 1 x 3N mesh in metres (a voice's PCA mean); the ends clamp.
// Throws std::invalid_argument for vertices outside the mesh.
double face_nose_angle_rad(const Eigen::Ref<const RowMajorMatrixXf>& mesh_m, const ArticulographyFacePoints& points,
                           double distance_mm);

// The registration of `ema` (named `source` in errors) onto the face `mesh_m`. Throws InputError
// "ema-coils" naming a coil of kEmaCoilsUsed the file lacks or never has a sample of, for upper-lip
// and upper-incisor coils less than 1 mm apart along x (no forward direction), or for a nose-bridge
// coil within 10 mm of the upper incisor.
EmaRegistration register_ema(const MarkerFrames<Millimetres>& ema, const std::string& source,
                             const Eigen::Ref<const RowMajorMatrixXf>& mesh_m, const ArticulographyFacePoints& points);

// Curves of the measures on one uniform grid t_j = j / rate_hz, j = 0 .. floor(end_s x rate_hz).
struct MeasureCurves {
  double rate_hz = 100;
  std::array<std::vector<double>, kArticulatoryMeasureCount> mm;
  std::size_t size() const { return mm[0].size(); }
};

// The real curves: each used coil's samples (gaps linearly bridged), relative to the mean upper
// incisor, low-passed at `lowpass_hz` (zero phase: zero_phase_lowpass.hpp), turned by the
// registration, measured and sampled linearly at the grid (frame k of the file at
// (first_frame + k) / frame_rate_hz s). Throws std::invalid_argument when end_s lies outside the track.
MeasureCurves ema_measure_curves(const MarkerFrames<Millimetres>& ema, const EmaRegistration& registration,
                                 double rate_hz, double end_s, double lowpass_hz = 15);

// The face's curves from the voice's PCA frames (F x k, 60 fps from t = 0: synthesize's track)
// on its mesh (mean 1 x 3N and components k x 3N, metres) and the tongue's FAPs (F x 5, FAP 43..47;
// the tip's height is FAP 44 x `mns_mm`, the face's MNS FAPU in mm as the renderer measures it on
// the neutral face), sampled linearly at the grid (the last frame held). Throws
// std::invalid_argument for shapes that disagree or an MNS that is not positive.
MeasureCurves face_measure_curves(const Eigen::Ref<const RowMajorMatrixXf>& mean_m,
                                  const Eigen::Ref<const RowMajorMatrixXf>& components_m, const Eigen::MatrixXf& pca_frames,
                                  const Eigen::MatrixXf& tongue, const ArticulographyFacePoints& points, double mns_mm,
                                  double rate_hz, double end_s);

// Settings of the comparison (the defaults are the spec's).
struct ArticulographySettings {
  double rate_hz = 100;     // the common grid
  double lowpass_hz = 15;   // the coils' low-pass
  double max_lag_s = 0.2;   // best lag searched within +-
  double lag_step_s = 0.001;
  double extra_rotation_rad = 0;  // added to the registration's rotation (a sensitivity check)
};

// One phone's share of the zero-lag correlation's loss 1 - r, per measure
// (correlation_loss_by_span): the grid's samples from the phone's start to the next phone's (the
// first phone's from 0, the last's to the grid's end). The shares of all phones add up to 1 - r.
struct PhoneLoss {
  Phone phone = Phone::SIL;
  double start_s = 0, end_s = 0;  // its span on the grid
  std::array<double, kArticulatoryMeasureCount> loss{};
};

struct ArticulographyEvaluation {
  EmaRegistration registration;
  ArticulographySettings settings;
  double ema_rate_hz = 0;
  std::int64_t ema_frames = 0;
  double end_s = 0;  // the EMA's last frame: the grid's span
  MeasureCurves real, face;
  std::array<TrajectoryAgreement, kArticulatoryMeasureCount> agreement;
  std::size_t phones = 0, units = 0;  // of the synthesis
  // Where the voice's units were cut from, and the phones they stand for (the synthesis
  // timeline's, one per target phone); both empty for the talker, which has no units.
  std::vector<UnitSource> unit_sources;
  std::vector<Phone> asked;
  std::vector<PhoneLoss> loss_by_phone;  // one per phone animated, in order
};

// What the comparison needs of its inputs, checked before any work: `ema` (named `ema_source`)
// has at least 3 frames starting at 0 (within 20 ms) at 100 Hz or more ("ema-too-short",
// "articulography-span", "ema-rate"), a sample of every coil of kEmaCoilsUsed and coils that
// give a head frame (register_ema's "ema-coils"), and covers the speech of `phones` (at
// `sample_rate`; `phones_source` in errors): some phone other than silence, none ending more than
// 20 ms after the EMA's last frame or starting before its first ("articulography-span"). Throws
// InputError.
void check_articulography_inputs(const MarkerFrames<Millimetres>& ema, const std::string& ema_source,
                                 std::span<const TimedPhone> phones, SampleRate sample_rate,
                                 const std::string& phones_source);

// Animates `phones` (at `sample_rate`, audio of `audio_samples`; `phones_source` names them in
// errors) on `voice` with `options`, then compares its face with `ema` (`ema_source`). Throws
// what check_articulography_inputs, register_ema and synthesize throw, and InputError
// "articulography-mesh" when the voice's face is not of the ICT topology.
ArticulographyEvaluation evaluate_articulography(const MarkerFrames<Millimetres>& ema, const std::string& ema_source,
                                                 const Voice& voice, std::span<const TimedPhone> phones,
                                                 SampleRate sample_rate, std::int64_t audio_samples,
                                                 const SynthesisOptions& options, const std::string& phones_source,
                                                 const ArticulographySettings& settings = {});

// The same comparison for the SYNTHETIC reference talker's own articulation of `phones`
// (talker/coarticulation.hpp: the Cohen-Massaro channel tracks the default voice's corpus is
// recorded from, mapped to ICT expression shapes on the generic ICT face at 60 fps), without a
// voice's units, RBF map or PCA: set beside evaluate_articulography's, it tells whether an error
// comes from the talker's tables or from the voice built on them. The tongue is the parametric
// tongue of the same phones, and the MNS FAPU the voice's, as there; `units` is 0.
ArticulographyEvaluation evaluate_talker_articulography(const MarkerFrames<Millimetres>& ema,
                                                        const std::string& ema_source, const Voice& voice,
                                                        std::span<const TimedPhone> phones, SampleRate sample_rate,
                                                        std::int64_t audio_samples, const SynthesisOptions& options,
                                                        const std::string& phones_source,
                                                        const ArticulographySettings& settings = {});

// The table `eval articulography` prints for one animation, headed by `title`: one row per
// measure (range real and ours in mm, their ratio, r at zero lag, best lag in ms, r there; a lag
// on the edge of the window is marked "(window edge)": no delay lines the curves up), then the
// registration.
std::string articulography_table(const ArticulographyEvaluation& e, const std::string& title);
// Where r is lost: one row per phone (its span in s and its share of 1 - r per measure), then
// the whole take's 1 - r, for lip aperture, jaw opening and lower-lip protrusion; headed by `title`.
std::string articulography_loss_table(const ArticulographyEvaluation& e, const std::string& title);
// Two animations of one EMA (the reference alignment's and fapcast's own): per measure the range
// ratio and r of both and the own one's change relative to the reference one's, in % (for r also
// the difference: near r = 0 a small change is a large percentage).
std::string alignment_effect_table(const ArticulographyEvaluation& reference, const ArticulographyEvaluation& own);

// The evaluation as JSON: EMA, settings, registration, synthesis, per measure the scores
// ("measures"), each phone's share of 1 - r ("loss_by_phone": phone, start_s, end_s, loss by
// measure) and both curves on the grid ("curves": rate_hz, real_mm and ours_mm by measure).
nlohmann::json articulography_json(const ArticulographyEvaluation& e);

// One panel per measure: the real curve and each animation's (named by `names`), each minus its
// median so that the shapes overlay; time in s on the grid.
LinePlot articulography_plot(std::span<const ArticulographyEvaluation> evaluations, std::span<const std::string> names,
                             const std::string& title);

}  // namespace fapcast
