#include "animation.hpp"

#include "fapcast/codec/bvh_export.hpp"
#include "fapcast/codec/bvh_text.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/transport/track_file.hpp"
#include "fap_output.hpp"

#include "file_extension.hpp"

namespace fapcast::cli {

bool is_animation_output(const std::filesystem::path& path) {
  return track_format_of(path).has_value() || is_mesh_output(path) || lower_extension(path) == ".bvh";
}

bool is_mesh_output(const std::filesystem::path& path) { return lower_extension(path) == ".glb"; }

TrackFileBytes animation_bytes(const std::filesystem::path& path, const FapSequence& seq, const FapTextWriteOptions& fap,
                               SampleRate sample_rate, const FeaturePointPositions& neutral) {
  if (lower_extension(path) == ".bvh") return {write_bvh(fap_to_bvh(seq, fit_generic_face(neutral))), {}};
  return track_file_bytes(path, seq, {.sample_rate = sample_rate, .fap = fap});
}

void write_animation(const std::filesystem::path& path, const FapSequence& seq, const FapTextWriteOptions& fap,
                     SampleRate sample_rate, const FeaturePointPositions& neutral) {
  TrackFileBytes out = animation_bytes(path, seq, fap, sample_rate, neutral);
  write_file_atomically(path, out.bytes);
  print_notes(path, out.notes);
}

}  // namespace fapcast::cli
