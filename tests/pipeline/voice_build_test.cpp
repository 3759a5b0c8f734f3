// The voice build end to end on a small SYNTHETIC corpus recorded by the reference talker: words
// chosen so that every one of the 21 viseme classes occurs.
#include "fapcast/builder/voice_build.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "support/corpus_conversion.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/lab_file.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/face/marker_map.hpp"
#include "fapcast/capture/preprocessing.hpp"
#include "fapcast/talker/reference_talker.hpp"
#include "fapcast/voice/voice.hpp"
#include "fapcast/builder/voice_corpus.hpp"
#include "fapcast/builder/voice_prototypes.hpp"
#include "fapcast/core/file_io.hpp"

namespace fapcast {
namespace {

namespace fs = std::filesystem;

// bob five thin dad see lull shoe red go we it bed hat father boy show good moon how: every class.
const char* const kWords[] = {"bob", "five", "thin", "dad", "see", "lull", "shoe", "red", "go", "we",
                              "it",  "bed",  "hat",  "father", "boy", "show", "good", "moon", "how", "sofa"};

class VoiceBuild : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    corpus_ = new fs::path(fs::temp_directory_path() / ("fapcast_voice_build_corpus_" + std::to_string(::getpid())));
    fs::remove_all(*corpus_);
    RecordingScript script;
    for (const char* w : kWords) script.items.push_back({ScriptSection::kCommonWord, w, {}, "", 0.0});
    (void)record_reference_corpus(script, *corpus_, {.count = 0, .seed = 2, .script = {}},
                                  [](const std::string& name, std::string_view bytes) {
                                    write_file_atomically(*corpus_ / name, bytes);
                                  });
  }
  // Built on first use: the refusal tests need only the corpus (CTest runs each test alone).
  static const BuiltVoice& built() {
    if (built_ == nullptr) {
      built_ = new BuiltVoice(build_voice(*corpus_, options()));
      voice_file_ = new fs::path(*corpus_ / "voice.fapv");
      write_file_atomically(*voice_file_, built_->bytes);
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

// FCOE row f is the PCA projection of the retargeting's image (the map and its lip-contact term) of corpus frame f.
TEST_F(VoiceBuild, FrameCoefficientsAreTheProjectedRetargetedFrames) {
  const Voice voice = Voice::open(voice_file());
  const CorpusListing listing = list_corpus(*corpus_);
  Eigen::Matrix3Xd reference(3, 5);
  for (Eigen::Index i = 0; i < 5; ++i) reference.col(i) = 100.0 * voice.rigid_markers()[static_cast<std::size_t>(i)].source_reference_m;
  const std::size_t u = 3;
  const CorpusTake take = read_corpus_take(listing, u);
  const Eigen::MatrixXd x = source_vectors_m(preprocess_take(take.markers, rigid_marker_rows(), reference).frames, "take");
  const FrameSpan span = voice.utterance_frames()[u];
  ASSERT_EQ(static_cast<Eigen::Index>(span.count), x.cols());
  const Eigen::RowVectorXd mean = voice.pca_mean().cast<double>();
  const Eigen::MatrixXd components = voice.pca_components().cast<double>();
  for (Eigen::Index f : {Eigen::Index{0}, x.cols() / 2, x.cols() - 1}) {
    const Eigen::VectorXd y = voice.retargeting()(x.col(f));
    const Eigen::VectorXd c = components * (y - mean.transpose());
    const Eigen::VectorXf stored = voice.frame_coefficients().row(span.first + f).transpose();
    EXPECT_LT((c.cast<float>() - stored).norm(), 1e-4f * (1.0f + stored.norm())) << "frame " << f;
    // And the PCA rebuild is close to the retargeted mesh (the map's image is ~17-dimensional).
    EXPECT_LT((mean.transpose() + components.transpose() * c - y).cwiseAbs().maxCoeff(), 2e-4) << "frame " << f;
  }
}

// Every /p b m/ of the corpus closes on the target face as played back (PCA frames): the map alone
// opens the closures the talker makes with rounded lips ("moon", "bob" next to "shoe"), the
// lip-contact term closes them to within half a millimetre of the talker's own closure.
TEST_F(VoiceBuild, EveryBilabialClosesOnTheTargetFace) {
  const Voice voice = Voice::open(voice_file());
  ASSERT_TRUE(built().summary.lip_contact);
  EXPECT_GT(built().summary.lip_contact_frames, 0);
  const LipContact& contact = *voice.retargeting().contact();
  Eigen::Index upper = -1, lower = -1;
  for (const auto& p : voice.feature_points()) {
    if (p.label == "2.2") upper = 3 * Eigen::Index{p.vertex} + 1;
    if (p.label == "2.3") lower = 3 * Eigen::Index{p.vertex} + 1;
  }
  ASSERT_GE(upper, 0);
  const auto mean = voice.pca_mean();
  const auto components = voice.pca_components();
  const auto coefficients = voice.frame_coefficients();
  const auto gap = [&](Eigen::Index f) {  // the played-back target's inner-lip gap, metres
    double g = mean(0, upper) - mean(0, lower);
    for (Eigen::Index c = 0; c < components.rows(); ++c) g += coefficients(f, c) * (components(c, upper) - components(c, lower));
    return g;
  };
  // The map alone, for comparison: its gap at a source frame.
  const CorpusListing listing = list_corpus(*corpus_);
  Eigen::Matrix3Xd reference(3, 5);
  for (Eigen::Index i = 0; i < 5; ++i) reference.col(i) = 100.0 * voice.rigid_markers()[static_cast<std::size_t>(i)].source_reference_m;
  int bilabials = 0, open_without = 0;
  double worst = -1.0;
  for (std::size_t u = 0; u < listing.utterances.size(); ++u) {
    const FrameSpan span = voice.utterance_frames()[u];
    const Eigen::MatrixXd x = source_vectors_m(
        preprocess_take(read_corpus_take(listing, u).markers, rigid_marker_rows(), reference).frames, "take");
    for (std::size_t s = 0; s < voice.graph().size(); ++s) {
      const PhoneState& state = voice.graph().state(static_cast<StateId>(s));
      if (state.utterance != u || state.viseme != VisemeClass::kBilabial) continue;
      ++bilabials;
      double least = 1e9, least_source = 1e9, least_map = 1e9;
      for (std::uint32_t f = state.frames.first; f < state.frames.first + state.frames.count; ++f) {
        least = std::min(least, gap(f));
        const Eigen::VectorXd source = x.col(f - span.first);
        least_source = std::min(least_source, contact.source_gap_m(source));
        const Eigen::VectorXd mapped = voice.retarget_map()(source);
        least_map = std::min(least_map, mapped(upper) - mapped(lower));
      }
      open_without += least_map > 0.002;
      const double allowed = contact.target_contact_m + std::max(0.0, least_source - contact.source_contact_m);
      worst = std::max(worst, least - allowed);
      EXPECT_LT(least, allowed + 0.0005) << "utterance " << u << " state " << s << ": the target's lips stay "
                                         << 1000 * least << " mm apart (the map alone: " << 1000 * least_map << " mm)";
    }
  }
  std::cout << bilabials << " /p b m/: " << open_without << " more than 2 mm open by the map alone; with the term "
            << "at most " << 1000 * worst << " mm above the talker's closure\n";
  EXPECT_GE(bilabials, 5);
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
    const std::string bytes = read_file(dir / "utt0002.c3d");
    write_file_atomically(dir / "utt0002.c3d", bytes.substr(0, bytes.size() / 2));
    const std::string message = refusal(dir);
    EXPECT_NE(message.find("utt0002.c3d: byte "), std::string::npos) << message;
    EXPECT_NE(message.find(": c3d-"), std::string::npos) << message;
    fs::remove_all(dir);
  }
  {
    const fs::path dir = copy_corpus("textgrid");
    std::string text = read_file(dir / "utt0005.TextGrid");
    text.replace(text.find("xmax = "), 7, "xmax = x");
    write_file_atomically(dir / "utt0005.TextGrid", text);
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
    // A time no sample count holds: the alignment's fault (the rule `animate` uses, exit 1).
    const fs::path dir = copy_corpus("huge");
    write_file_atomically(dir / "utt0011.TextGrid", "File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\n0\n1e300\n"
                                                    "<exists>\n1\n\"IntervalTier\"\n\"phones\"\n0\n1e300\n1\n0\n1e300\n\"sil\"\n");
    const std::string message = refusal(dir);
    EXPECT_NE(message.find("utt0011.TextGrid: time-off-sample-grid: its end: time 1e+300 s is off the sample grid of 60 Hz"),
              std::string::npos) << message;
    fs::remove_all(dir);
  }
  {
    const fs::path dir = copy_corpus("manifest");
    write_file_atomically(dir / "manifest.json", "{\"utterances\": 3}");
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

// The same SYNTHETIC takes delivered as TRC or marker CSV with HTK/MOCHA .lab alignments build
// the same voice, byte for byte, as the C3D + TextGrid original (the writers spell the C3D's
// float samples and the TextGrid's times exactly, so nothing is lost in the conversion).
TEST_F(VoiceBuild, TrcAndCsvWithLabBuildTheSameVoiceAsC3dWithTextGrid) {
  for (const test::MarkerFormat format : {test::MarkerFormat::trc, test::MarkerFormat::csv}) {
    const std::string ext = test::extension_of(format).substr(1);
    const fs::path dir = fs::temp_directory_path() / ("fapcast_voice_" + ext + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    test::convert_corpus(*corpus_, dir, format, test::AlignmentFormat::lab);
    ASSERT_TRUE(fs::exists(dir / ("utt0001." + ext)));
    ASSERT_TRUE(fs::exists(dir / "utt0001.lab"));
    EXPECT_EQ(build_voice(dir, options()).bytes, built().bytes) << ext << " + lab";
    fs::remove_all(dir);
  }
}

bool same_take(const CorpusTake& a, const CorpusTake& b) {
  const Eigen::MatrixXd& x = a.markers.positions;
  const Eigen::MatrixXd& y = b.markers.positions;
  return a.phones == b.phones && a.markers.labels == b.markers.labels && x.rows() == y.rows() && x.cols() == y.cols() &&
         ((x.array() == y.array()) || (x.array().isNaN() && y.array().isNaN())).all() &&
         std::equal(a.spans.begin(), a.spans.end(), b.spans.begin(), b.spans.end(),
                    [](const FrameSpan& p, const FrameSpan& q) { return p.first == q.first && p.count == q.count; });
}

// A 120 fps TRC (every other frame the original, the ones between interpolated) is resampled to
// the original 60 fps takes exactly; without a manifest, pairing by stem finds the same takes.
TEST_F(VoiceBuild, A120FpsTrcIsResampledToTheOriginalTakes) {
  const fs::path dir = fs::temp_directory_path() / ("fapcast_voice_trc120_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  test::convert_corpus(*corpus_, dir, test::MarkerFormat::trc, test::AlignmentFormat::lab, 2);
  const CorpusListing original = list_corpus(*corpus_);
  for (const bool with_manifest : {true, false}) {
    if (!with_manifest) fs::remove(dir / "manifest.json");
    const CorpusListing listing = list_corpus(dir);
    ASSERT_EQ(listing.utterances.size(), original.utterances.size());
    for (std::size_t u = 0; u < listing.utterances.size(); ++u) {
      EXPECT_EQ(listing.utterances[u].id, original.utterances[u].id);
      const CorpusTake take = read_corpus_take(listing, u);
      EXPECT_EQ(take.capture_frame_rate_hz, 120);
      EXPECT_TRUE(same_take(take, read_corpus_take(original, u))) << listing.utterances[u].id;
    }
  }
  fs::remove_all(dir);
}

// TIMIT labels in a .lab (lower case, stops split into closure + release, h# for silence) give
// the same phone states as the ARPAbet TextGrid they were made from.
TEST_F(VoiceBuild, TimitLabelsWithClosuresGiveTheSamePhoneStates) {
  const fs::path dir = fs::temp_directory_path() / ("fapcast_voice_timit_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  test::convert_corpus(*corpus_, dir, test::MarkerFormat::csv, test::AlignmentFormat::lab);
  const CorpusListing original = list_corpus(*corpus_);
  std::size_t closures = 0;
  for (const CorpusUtterance& u : original.utterances) {
    const Alignment grid = read_textgrid(read_file(u.alignment), u.alignment.string());
    LabFile lab;
    lab.unit = LabTimeUnit::seconds;
    for (const Interval& iv : grid.find("phones")->intervals) {
      std::string label;
      for (char c : iv.label)
        if (!std::isdigit(static_cast<unsigned char>(c))) label += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (label.empty() || label == "sil") label = "h#";
      if (label.size() == 1 && std::string("bdgptk").find(label[0]) != std::string::npos) {
        const double mid = (iv.start_s + iv.end_s) / 2;
        lab.segments.push_back({iv.start_s, mid, label + "cl"});
        lab.segments.push_back({mid, iv.end_s, label});
        ++closures;
      } else {
        lab.segments.push_back({iv.start_s, iv.end_s, label});
      }
    }
    write_file_atomically(dir / (u.id + ".lab"), write_lab(lab));
  }
  EXPECT_GT(closures, 10u);
  std::string manifest = read_file(dir / "manifest.json");
  manifest.insert(1, "\"phone_set\": \"timit\", ");
  write_file_atomically(dir / "manifest.json", manifest);
  const CorpusListing listing = list_corpus(dir);
  EXPECT_EQ(listing.phone_set, CorpusPhoneSet::timit);
  for (std::size_t u = 0; u < listing.utterances.size(); ++u) {
    const CorpusTake take = read_corpus_take(listing, u);
    const CorpusTake want = read_corpus_take(original, u);
    EXPECT_EQ(take.phones, want.phones) << listing.utterances[u].id;
    EXPECT_TRUE(same_take(take, want)) << listing.utterances[u].id;
  }
  fs::remove_all(dir);
}

// Named bad corpora (tests/data/corpus/bad-corpora/bad.NNN.<rule>/, made by
// make_bad_corpora.py): each is refused with its rule, and the message is the golden one.
TEST(VoiceCorpusBadCorpora, AreRefusedWithTheGoldenMessages) {
  const fs::path root = fs::path(FAPCAST_TEST_DATA) / "corpus" / "bad-corpora";
  std::map<std::string, std::string> golden;
  {
    std::istringstream lines(read_file(root / "EXPECTED.txt"));
    for (std::string line; std::getline(lines, line);)
      if (!line.empty() && line[0] != '#') golden[line.substr(0, line.find('/'))] = line;
  }
  const bool regenerate = std::getenv("FAPCAST_REGENERATE") != nullptr;
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(root))
    if (e.is_directory()) names.insert(e.path().filename().string());
  ASSERT_GE(names.size(), 11u);
  std::string regenerated;
  for (const std::string& name : names) {
    std::string message = "accepted";
    try {
      const CorpusListing listing = list_corpus(root / name);
      for (std::size_t u = 0; u < listing.utterances.size(); ++u) (void)read_corpus_take(listing, u);
    } catch (const InputError& e) {
      message = e.what();
      const std::string rule = name.substr(8);  // bad.NNN.<rule>
      EXPECT_EQ(e.rule(), rule) << message;
    }
    const std::string prefix = (root / "").string();
    if (message.rfind(prefix, 0) == 0) message = message.substr(prefix.size());
    regenerated += message + "\n";
    if (!regenerate) {
      EXPECT_EQ(message, golden[name]) << name;
    }
  }
  if (regenerate) {
    std::ofstream(root / "EXPECTED.txt") << "# Golden refusals of the named bad corpora (regenerate: FAPCAST_REGENERATE=1 "
                                            "fapcast_pipeline_tests --gtest_filter=*BadCorpora*)\n"
                                         << regenerated;
  }
  EXPECT_EQ(golden.size(), names.size());
}

}  // namespace
}  // namespace fapcast
