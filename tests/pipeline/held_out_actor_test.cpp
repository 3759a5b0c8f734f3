// held_out_actor: held-out takes are recorded by the actor of the voice's own corpus (its
// corpus_seed), never by the one the build's EM-PCA seed would name.
#include "fapcast/eval/synthesis_evaluation.hpp"
#include "fapcast/talker/reference_talker.hpp"
#include "fapcast/voice/voice.hpp"
#include "support/tiny_voice.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fapcast::test {
namespace {

std::string refusal(const TinyVoice& tiny, const std::string& name) {
  const Voice voice = tiny.open(name);
  try {
    (void)held_out_actor(voice);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(HeldOutActor, IsTheActorOfTheCorpusSeedNotOfTheBuildSeed) {
  TinyVoice tiny;
  tiny.provenance.seed = 1;  // the build's EM-PCA start
  tiny.provenance.parameters["corpus_seed"] = 4;
  const FaceModel actor = held_out_actor(tiny.open("held_out_actor_4.fapv"));
  const FaceModel expected = reference_actor(ict_face_model(), 4);
  const FaceModel other = reference_actor(ict_face_model(), 1);
  ASSERT_EQ(actor.neutral_cm.cols(), expected.neutral_cm.cols());
  EXPECT_EQ((actor.neutral_cm - expected.neutral_cm).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT((actor.neutral_cm - other.neutral_cm).cwiseAbs().maxCoeff(), 0.1) << "seeds 1 and 4 are other faces (cm)";
}

TEST(HeldOutActor, RefusesVoicesOfNoKnownReferenceCorpus) {
  TinyVoice tiny;
  tiny.provenance.parameters.erase("corpus_seed");
  std::string what = refusal(tiny, "held_out_actor_none.fapv");
  EXPECT_NE(what.find("held_out_actor_none.fapv: "), std::string::npos) << what;
  EXPECT_NE(what.find("no provenance parameter corpus_seed"), std::string::npos) << what;

  for (double bad : {-1.0, 2.5, 1e17}) {
    tiny.provenance.parameters["corpus_seed"] = bad;
    what = refusal(tiny, "held_out_actor_bad.fapv");
    EXPECT_NE(what.find("corpus_seed"), std::string::npos) << bad << ": " << what;
    EXPECT_NE(what.find("is not a whole number"), std::string::npos) << bad << ": " << what;
  }

  tiny.provenance.parameters["corpus_seed"] = 2;
  tiny.provenance.synthetic = false;
  what = refusal(tiny, "held_out_actor_real.fapv");
  EXPECT_NE(what.find("held_out_actor_real.fapv: "), std::string::npos) << what;
  EXPECT_NE(what.find("not"), std::string::npos) << what;
  EXPECT_NE(what.find("reference corpus"), std::string::npos) << what;
}

}  // namespace
}  // namespace fapcast::test
