#pragma once
// The visual prototypes of Ma et al. 2006, section 3.4: one source prototype per search viseme
// class, chosen from the corpus frames, and the matching target prototype on the target face, a
// recipe of ICT expression-shape weights. A recipe is the reference articulation
// (talker/articulation.hpp) as the corpus realises it at the class's centre frames, mapped to
// shape weights, plus the class's details (spec/prototypes.tsv, spec/voice.md "Target
// prototypes"). The RBF map of section 3.5 is trained on these pairs.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/core/input_error.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/select/phone_graph.hpp"
#include "fapcast/phonetics/viseme.hpp"
#include "fapcast/talker/articulation.hpp"

namespace fapcast {

// One detail row: `weight` of ICT expression `shape` added to class `viseme`'s recipe.
struct PrototypeShapeWeight {
  VisemeClass viseme;
  std::string_view shape;
  float weight;
};

// The details of all 21 classes, in spec/prototypes.tsv order (a test checks they agree).
std::span<const PrototypeShapeWeight> target_prototype_details();

// spec/prototypes.tsv as read from disk (4 columns).
struct PrototypeSpecRow {
  std::string viseme_class;  // viseme_class_name()
  std::string shape;
  float weight = 0;          // added to the articulation's weight of the shape
  std::string why;           // the visible detail the 8 channels do not carry
};
// Throws InputError (file:line: rule).
std::vector<PrototypeSpecRow> read_prototype_spec(const std::filesystem::path& file);

// Articulatory channel values, indexed by Channel.
using ChannelValues = std::array<float, kChannelCount>;

// The reference articulation as a corpus realises it: per viseme class, the mean channel values
// at the centre frames of the class's phone segments (the frames source prototypes are chosen
// from), each take coarticulated from its own alignment (Cohen-Massaro over spec/articulation.tsv,
// effort 1).
class RealisedArticulation {
 public:
  // One take: its phone segments in time order and their spans on the 60 fps voice grid, relative
  // to the take (CorpusTake::phones and ::spans). A segment's centre frame is first + count / 2.
  // Throws std::invalid_argument when the sizes differ or a span is empty or out of order.
  void add_take(std::span<const Phone> phones, std::span<const FrameSpan> spans);
  std::size_t count(VisemeClass v) const { return count_[static_cast<std::size_t>(v)]; }
  // Throws std::invalid_argument when the class has no segment.
  ChannelValues mean(VisemeClass v) const;

 private:
  std::array<std::array<double, kChannelCount>, kVisemeClassCount> sum_{};
  std::array<std::size_t, kVisemeClassCount> count_{};
};

// The mean channel targets of the class's phones (spec/visemes.tsv): what the articulation aims
// at, which coarticulation undershoots in running speech.
ChannelValues nominal_class_channels(VisemeClass v);

// A class's recipe on `face`: ShapeMapper(channels) plus the class's details, clamped to [0, 1];
// one weight per face expression.
std::vector<float> target_prototype_weights(const FaceModel& face, VisemeClass v, const ChannelValues& channels);

// The target prototypes of `classes` on `face` for the channel values `channels` (one per class):
// one row per class, the neutral mesh plus the class's recipe, D = 3N columns (xyz interleaved per
// vertex), METRES. Throws std::out_of_range when the face lacks a shape of the tables,
// std::invalid_argument when the sizes differ.
Eigen::MatrixXd target_prototype_meshes(const FaceModel& face, std::span<const VisemeClass> classes,
                                        std::span<const ChannelValues> channels);

// Rank of the rows of `rows` after subtracting their mean: singular values above
// relative_tolerance x the largest count. k PCA components of the retargeted corpus are only
// meaningful up to this rank (the image of the RBF map lies in the span of the centred targets).
// The default sits well above the rounding noise of float32 meshes (~3e-7 relative on the ICT
// prototypes) and below their smallest real direction (~4e-4).
Eigen::Index centred_rank(const Eigen::MatrixXd& rows, double relative_tolerance = 1e-5);

// How a source prototype is chosen (recorded in every voice's provenance).
inline constexpr std::string_view kSourcePrototypeRule =
    "per viseme class, of the centre frames of the class's phone states, the one nearest the "
    "mean of those centre frames (Euclidean, source marker space after head-pose removal; "
    "earliest frame on ties)";

// How a target prototype is made (recorded in every voice's provenance).
inline constexpr std::string_view kTargetPrototypeRule =
    "per viseme class, the reference articulation's channel values (spec/articulation.tsv, effort 1) "
    "averaged over the centre frames of the class's phone states, mapped by "
    "spec/articulation_shapes.tsv, plus the spec/prototypes.tsv details, over the ICT expression shapes";

struct SourcePrototype {
  VisemeClass viseme = VisemeClass::kSilence;
  Eigen::Index frame = 0;       // column of the source frames
  std::size_t candidates = 0;   // phone states of the class in the corpus
};

// Applies kSourcePrototypeRule: `frames` is d x F (one source marker vector per column),
// `states` the corpus's phone states (spans index the columns). Returns one prototype per class
// that occurs, in class order; a class with no state is absent. Throws std::invalid_argument when
// a span lies outside the frames or is empty.
std::vector<SourcePrototype> select_source_prototypes(const Eigen::MatrixXd& frames,
                                                      std::span<const PhoneState> states);

// The frame at the centre of a span: first + count / 2 (source prototypes are taken there, and
// the realised articulation the target prototypes follow is measured there).
inline Eigen::Index centre_frame(const FrameSpan& frames) {
  return static_cast<Eigen::Index>(frames.first) + static_cast<Eigen::Index>(frames.count / 2);
}
inline Eigen::Index centre_frame(const PhoneState& s) { return centre_frame(s.frames); }

}  // namespace fapcast
