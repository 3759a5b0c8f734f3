#pragma once
// Reading and writing BVH text in the layout Blender's importer expects (spec/bvh.md): HIERARCHY,
// ROOT/JOINT blocks with OFFSET then CHANNELS, End Site, MOTION, Frames:, Frame Time:, one line
// of values per frame.
#include "fapcast/core/input_error.hpp"
#include "fapcast/codec/bvh_document.hpp"

#include <string>
#include <string_view>

namespace fapcast {

// Hard limits of the reader, so hostile files cannot exhaust memory or the stack.
inline constexpr std::size_t kBvhMaxJoints = 4096;
inline constexpr std::size_t kBvhMaxDepth = 256;

// Parses a whole BVH file. `source` names it in messages. Throws InputError with the line and
// the rule broken (spec/bvh.md lists the rules). Never allocates from the Frames: count: it
// reads the motion lines that are there and then checks the count.
BvhDocument read_bvh(std::string_view bytes, std::string_view source);

// Writes `doc`: tab indentation, LF, numbers in the shortest fixed notation that reads back to
// the same double. Throws std::invalid_argument when doc breaks its own invariants (no joints,
// a name with whitespace, a parent out of order, motion size != frame_count * channel_count()).
std::string write_bvh(const BvhDocument& doc);

}  // namespace fapcast
