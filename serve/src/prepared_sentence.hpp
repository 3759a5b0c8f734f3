#pragma once
// A sentence of a session, synthesised and FBA-encoded on a synthesis thread, ready to stream.
#include "fapcast/transport/media_unit.hpp"
#include "fapcast/utterance/speaker.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace fapcast {

struct PreparedSentence {
  std::size_t index = 0;
  std::string text;
  SpokenSentence spoken;
  std::vector<MediaUnit> units;  // one FBA access unit per frame; samples on the sentence's audio
  std::shared_ptr<const Speaker> speaker;  // the speaker that spoke it
  std::string error;  // non-empty: synthesis refused the sentence
};

}  // namespace fapcast
