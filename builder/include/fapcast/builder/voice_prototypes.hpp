#pragma once
// The visual prototypes of Ma et al. 2006, section 3.4: one source prototype per search viseme
// class, chosen from the corpus frames, and the matching target prototype on the target face, a
// recipe of ICT expression-shape weights (spec/prototypes.tsv). The RBF map of section 3.5 is
// trained on these pairs.
#include <Eigen/Core>
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

namespace fapcast {

// One row of the target-prototype table: `weight` of ICT expression `shape` in class `viseme`.
struct PrototypeShapeWeight {
  VisemeClass viseme;
  std::string_view shape;
  float weight;
};

// The recipes of all 21 classes, in spec/prototypes.tsv order (a test checks they agree).
std::span<const PrototypeShapeWeight> target_prototype_table();

// spec/prototypes.tsv as read from disk (5 columns).
struct PrototypeSpecRow {
  std::string viseme_class;  // viseme_class_name()
  std::string shape;
  float weight = 0;
  std::string basis;  // "articulation", "articulation+detail" or "detail"
  std::string why;    // the argument for a detail, "-" for pure articulation rows
};
// Throws InputError (file:line: rule).
std::vector<PrototypeSpecRow> read_prototype_spec(const std::filesystem::path& file);

// The target prototypes of `classes` on `face`: one row per class, the neutral mesh plus the
// class's recipe, D = 3N columns (xyz interleaved per vertex), METRES. Throws std::out_of_range
// when the face lacks a shape of the table.
Eigen::MatrixXd target_prototype_meshes(const FaceModel& face, std::span<const VisemeClass> classes);

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

// The frame at the centre of a state: first + count / 2.
inline Eigen::Index centre_frame(const PhoneState& s) {
  return static_cast<Eigen::Index>(s.frames.first) + static_cast<Eigen::Index>(s.frames.count / 2);
}

}  // namespace fapcast
