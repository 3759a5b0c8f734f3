#pragma once
// The outputs of `say` and `animate`: a FAP track (fapcast/utterance/fap_track.hpp) or a mesh,
// to a file chosen by extension. Wiring only: each step is a library function.
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/transport/track_file.hpp"
#include "fapcast/utterance/fap_track.hpp"

#include <cstdint>
#include <filesystem>

namespace fapcast::cli {

// Whether `path` names an output `say`/`animate` can write (.fap, .fba, .json, .bvh, .glb).
bool is_animation_output(const std::filesystem::path& path);
// Whether it is the mesh output (.glb), which takes the voice's PCA frames, not FAPs.
bool is_mesh_output(const std::filesystem::path& path);

// The bytes of `seq` in the format of the extension of `path` (which is not written), and the
// notes for the user; .json carries each frame's sample at `sample_rate`, .bvh is rigged on the
// neutral face (fit_generic_face supplies pivots and the tongue tip).
TrackFileBytes animation_bytes(const std::filesystem::path& path, const FapSequence& seq, const FapTextWriteOptions& fap,
                               SampleRate sample_rate, const FeaturePointPositions& neutral);

// Writes animation_bytes(...) atomically and prints its notes.
void write_animation(const std::filesystem::path& path, const FapSequence& seq, const FapTextWriteOptions& fap,
                     SampleRate sample_rate, const FeaturePointPositions& neutral);

}  // namespace fapcast::cli
