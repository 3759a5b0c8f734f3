#pragma once
// A voice adapted to a specific face of its face's topology without re-recording (paper
// section 3.9, spec/adaptation.md "Re-targeting a voice"): every target-space quantity of the
// voice is carried through the per-vertex maps of FaceAdaptation(generic, specific); the PCA
// coefficients, the phone graph and the unit search are unchanged.
#include <string>

#include "fapcast/face/mesh_types.hpp"
#include "fapcast/voice/voice.hpp"

namespace fapcast {

struct VoiceAdaptationSummary {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t degenerate_triangles = 0;      // weight 0 in the per-vertex means
  std::size_t global_map_vertices = 0;       // vertices that took the global map
  double max_feature_point_offset_m = 0;     // largest |specific - generic| at a feature point
};

struct AdaptedVoice {
  std::string bytes;  // the new voice file (write with write_file_atomically)
  VoiceAdaptationSummary summary;
};

// generic_m: the voice's own neutral face (3 x N, metres); specific_m: the specific neutral face
// (3 x N, metres, same faces). The new voice holds
//   PMEA  specific + A (mean - generic)        PCOM  A pc_k for each component (not orthonormal)
//   ROFF  specific + A (b - generic)           RWEI  A w_j for each RBF weight row
//   FPNT  feature points and rigid markers at the specific neutral (so the FAPU are its own)
//   FMAP  A composed with the voice's previous maps (expressions are carried the same way)
//   PROV  target_face "<old> re-targeted to <specific_name>", note "retarget"
// and every other section (PVAR, FCOE, RCEN, RPAR, GRPH, unknown ones) byte for byte.
// Throws std::invalid_argument when N differs from the voice's or generic_m is not the voice's
// neutral face (a feature point more than 0.1 mm from FPNT's position: rule generic-mismatch,
// naming the point), and FaceAdaptation's errors for bad faces.
AdaptedVoice adapt_voice(const Voice& voice, const Positions& generic_m, const Positions& specific_m,
                               const PolygonFaces& faces, const std::string& specific_name);

}  // namespace fapcast
