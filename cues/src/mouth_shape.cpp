#include "fapcast/cues/mouth_shape.hpp"

namespace fapcast {

std::optional<MouthShape> mouth_shape_from_letter(char c) {
  for (const MouthShapeInfo& row : kMouthShapeTable)
    if (row.letter == c) return row.shape;
  return std::nullopt;
}

std::optional<MouthShapeSet> drawn_shapes(std::string_view extended) {
  MouthShapeSet drawn{MouthShape::A, MouthShape::B, MouthShape::C, MouthShape::D, MouthShape::E, MouthShape::F};
  for (char c : extended) {
    const std::optional<MouthShape> s = mouth_shape_from_letter(c);
    if (!s || !mouth_shape_info(*s).extended || drawn.contains(*s)) return std::nullopt;
    drawn.insert(*s);
  }
  return drawn;
}

std::string extended_letters(MouthShapeSet drawn) {
  std::string out;
  for (const MouthShapeInfo& row : kMouthShapeTable)
    if (row.extended && drawn.contains(row.shape)) out += row.letter;
  return out;
}

}  // namespace fapcast
