// The voice build end to end on a small SYNTHETIC corpus recorded by the reference talker: words
// chosen so that every one of the 21 viseme classes occurs.
#include "fapcast/synth/voice_build.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <set>

#include "fapcast/synth/input_error.hpp"
#include "fapcast/synth/marker_map.hpp"
#include "fapcast/synth/preprocessing.hpp"
#include "fapcast/synth/reference_talker.hpp"
#include "fapcast/synth/voice.hpp"
#include "fapcast/synth/voice_corpus.hpp"
#include "fapcast/synth/voice_prototypes.hpp"
#include "fapcast/transport/file_io.hpp"

namespace fapcast::synth {
namespace {

namespace fs = std::filesystem;

// bob five thin dad see lull shoe red go we it bed hat father boy show good moon how: every class.
const char* const kWords[] = {"bob", "five", "thin", "dad", "see", "lull", "shoe", "red", "go", "we",
                              "it",  "bed",  "hat",  "father", "boy", "show", "good", "moon", "how"};

class VoiceBuild : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    corpus_ = new fs::path(fs::temp_directory_path() / ("fapcast_voice_build_corpus_" + std::to_string(::getpid())));
    fs::remove_all(*corpus_);
    RecordingScript script;
    for (const char* w : kWords) script.items.push_back({ScriptSection::kCommonWord, w, {}, "", 0.0});
    (void)record_reference_corpus(script, *corpus_, {.count = 0, .seed = 2, .script = {}},
                                  [](const std::string& name, std::string_view bytes) {
                                    transport::write_file_atomically(*corpus_ / name, bytes);
                                  });
  }
  // Built on first use: the refusal tests need only the corpus (CTest runs each test alone).
  static const BuiltVoice& built() {
    if (built_ == nullptr) {
      built_ = new BuiltVoice(build_voice(*corpus_, options()));
      voice_file_ = new fs::path(*corpus_ / "voice.fapv");
      transport::write_file_atomically(*voice_file_, built_->bytes);
    }
    return *built_;
  }
  static const fs::path& voice_file() {
    (void)built();
    return *voice_file_;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*corpus_);
    delete corpus_;
    delete built_;
    delete voice_file_;
    built_ = nullptr;
    voice_file_ = nullptr;
  }
  static VoiceBuildOptions options() {
    VoiceBuildOptions o;
    o.build_time_utc = "2026-11-22T05:00:00Z";
    o.tool_version = "test";
    o.corpus_name = "voice_build_test corpus";
    return o;
  }
  // A copy of the corpus to break.
  static fs::path copy_corpus(const std::string& tag) {
    const fs::path dir = fs::temp_directory_path() / ("fapcast_voice_bad_" + tag + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& e : fs::directory_iterator(*corpus_))
      if (e.path().extension() != ".wav" && e.path().extension() != ".fapv") fs::copy_file(e.path(), dir / e.path().filename());
    return dir;
  }
  static std::string refusal(const fs::path& dir) {
    try {
      (void)build_voice(dir, options());
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  }

  static fs::path* corpus_;
  static BuiltVoice* built_;
  static fs::path* voice_file_;
};

fs::path* VoiceBuild::corpus_ = nullptr;
BuiltVoice* VoiceBuild::built_ = nullptr;
fs::path* VoiceBuild::voice_file_ = nullptr;

TEST_F(VoiceBuild, BuildsAVoiceThatOpens) {
  const VoiceBuildSummary& s = built().summary;
  EXPECT_EQ(s.utterances, std::size(kWords));
  EXPECT_EQ(s.prototypes, 21u);
  EXPECT_EQ(s.target_rank, 18);
  EXPECT_GT(s.frames, 20 * static_cast<std::int64_t>(std::size(kWords)));
  EXPECT_GT(s.r_squared_m2, 0);
  EXPECT_GT(s.explained_fraction, 0.999);  // the image of the map has rank <= 18: 17 of them hold it
  const Voice voice = Voice::open(voice_file());
  EXPECT_EQ(voice.component_count(), 17);
  EXPECT_EQ(voice.dimension(), 3 * ict_face_model().vertex_count());
  EXPECT_EQ(voice.frame_coefficients().rows(), s.frames);
  EXPECT_EQ(voice.graph().size(), s.states);
  EXPECT_EQ(voice.utterance_frames().size(), s.utterances);
  EXPECT_TRUE(voice.provenance().synthetic);
  EXPECT_EQ(voice.provenance().corpus, "voice_build_test corpus");
  EXPECT_EQ(voice.provenance().notes.at("prototype_rule"), std::string(kSourcePrototypeRule));
  EXPECT_EQ(voice.provenance().parameters.at("k"), 17);
  EXPECT_EQ(voice.provenance().parameters.at("corpus_seed"), 2);
  // Every class occurs; each state's phone is of its class; no state is empty.
  std::set<VisemeClass> classes;
  for (std::size_t j = 0; j < voice.graph().size(); ++j) {
    const PhoneState& st = voice.graph().state(static_cast<StateId>(j));
    EXPECT_EQ(search_viseme(voice.state_phones()[j]), st.viseme);
    EXPECT_GT(st.frames.count, 0u);
    classes.insert(st.viseme);
  }
  EXPECT_EQ(classes.size(), kVisemeClassCount);
  // The feature points are the 34 non-rigid markers, in table order, on the generic neutral.
  ASSERT_EQ(voice.feature_points().size(), 34u);
  const auto rows = source_marker_rows();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& p = voice.feature_points()[i];
    EXPECT_EQ(p.label, marker_sites()[rows[i]].label);
    EXPECT_TRUE(p.neutral_m.isApprox(ict_face_model().neutral_cm.col(p.vertex).cast<double>() / 100.0));
  }
  EXPECT_EQ(voice.rigid_markers().size(), 5u);
}

// FCOE row f is the PCA projection of the RBF map's image of corpus frame f.
TEST_F(VoiceBuild, FrameCoefficientsAreTheProjectedRetargetedFrames) {
  const Voice voice = Voice::open(voice_file());
  const CorpusListing listing = list_corpus(*corpus_);
  Eigen::Matrix3Xd reference(3, 5);
  for (Eigen::Index i = 0; i < 5; ++i) reference.col(i) = 100.0 * voice.rigid_markers()[static_cast<std::size_t>(i)].source_reference_m;
  const std::size_t u = 3;
  const CorpusTake take = read_corpus_take(listing, u);
  const Eigen::MatrixXd x = source_vectors_m(preprocess_take(take.markers, reference).frames, "take");
  const FrameSpan span = voice.utterance_frames()[u];
  ASSERT_EQ(static_cast<Eigen::Index>(span.count), x.cols());
  const Eigen::RowVectorXd mean = voice.pca_mean().cast<double>();
  const Eigen::MatrixXd components = voice.pca_components().cast<double>();
  for (Eigen::Index f : {Eigen::Index{0}, x.cols() / 2, x.cols() - 1}) {
    const Eigen::VectorXd y = voice.retarget_map()(x.col(f));
    const Eigen::VectorXd c = components * (y - mean.transpose());
    const Eigen::VectorXf stored = voice.frame_coefficients().row(span.first + f).transpose();
    EXPECT_LT((c.cast<float>() - stored).norm(), 1e-4f * (1.0f + stored.norm())) << "frame " << f;
    // And the PCA rebuild is close to the retargeted mesh (the map's image is ~17-dimensional).
    EXPECT_LT((mean.transpose() + components.transpose() * c - y).cwiseAbs().maxCoeff(), 2e-4) << "frame " << f;
  }
}

TEST_F(VoiceBuild, IsDeterministic) {
  EXPECT_EQ(build_voice(*corpus_, options()).bytes, built().bytes);
}

TEST_F(VoiceBuild, RefusesBadCorporaNamingFileAndRule) {
  EXPECT_NE(refusal(*corpus_ / "no-such-dir").find("corpus-missing"), std::string::npos);
  {
    const fs::path empty = copy_corpus("empty");
    for (const auto& e : fs::directory_iterator(empty)) fs::remove(e.path());
    EXPECT_NE(refusal(empty).find("corpus-empty"), std::string::npos) << refusal(empty);
    fs::remove_all(empty);
  }
  {
    const fs::path dir = copy_corpus("c3d");
    const std::string bytes = transport::read_file(dir / "utt0002.c3d");
    transport::write_file_atomically(dir / "utt0002.c3d", bytes.substr(0, bytes.size() / 2));
    const std::string message = refusal(dir);
    EXPECT_NE(message.find("utt0002.c3d: byte "), std::string::npos) << message;
    EXPECT_NE(message.find(": c3d-"), std::string::npos) << message;
    fs::remove_all(dir);
  }
  {
    const fs::path dir = copy_corpus("textgrid");
    std::string text = transport::read_file(dir / "utt0005.TextGrid");
    text.replace(text.find("xmax = "), 7, "xmax = x");
    transport::write_file_atomically(dir / "utt0005.TextGrid", text);
    const std::string message = refusal(dir);
    EXPECT_NE(message.find("utt0005.TextGrid:"), std::string::npos) << message;
    EXPECT_NE(message.find(": textgrid-"), std::string::npos) << message;
    fs::remove_all(dir);
  }
  {
    const fs::path dir = copy_corpus("length");  // "father"'s alignment beside "it"'s markers
    fs::copy_file(dir / "utt0014.TextGrid", dir / "utt0011.TextGrid", fs::copy_options::overwrite_existing);
    const std::string message = refusal(dir);
    EXPECT_NE(message.find("utt0011.TextGrid: corpus-length: "), std::string::npos) << message;
    fs::remove_all(dir);
  }
  {
    const fs::path dir = copy_corpus("manifest");
    transport::write_file_atomically(dir / "manifest.json", "{\"utterances\": 3}");
    EXPECT_NE(refusal(dir).find("manifest.json: corpus-manifest: "), std::string::npos) << refusal(dir);
    fs::remove(dir / "utt0007.c3d");
    fs::remove(dir / "manifest.json");  // scanned: utt0007.TextGrid has no c3d: fine; remove a grid instead
    fs::remove(dir / "utt0008.TextGrid");
    EXPECT_NE(refusal(dir).find("utt0008.TextGrid: corpus-file-missing: "), std::string::npos) << refusal(dir);
    fs::remove_all(dir);
  }
  {
    const fs::path dir = copy_corpus("few");  // one word: too few viseme classes for k = 17
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().rfind("utt0001.", 0) != 0) fs::remove(e.path());
    const std::string message = refusal(dir);
    EXPECT_NE(message.find("voice-prototypes: "), std::string::npos) << message;
    fs::remove_all(dir);
  }
}

}  // namespace
}  // namespace fapcast::synth
