#pragma once
// A small SYNTHETIC voice on the full ICT face for tests that speak: the reference talker records
// 19 words that hold every viseme class (seed 2) and the voice is built from them as `voice build`
// does; once per process, in a temporary directory removed at exit. Link fapcast::talker and
// fapcast::builder.
#include "fapcast/builder/voice_build.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/talker/reference_talker.hpp"
#include "support/run_command.hpp"

#include <filesystem>
#include <string>

namespace fapcast::test {

inline const std::filesystem::path& spoken_voice_file() {
  static const std::filesystem::path file = [] {
    const std::filesystem::path dir = make_temp_dir("spoken_voice");
    RecordingScript script;
    for (const char* w : {"bob", "five", "thin", "dad", "see", "lull", "shoe", "red", "go", "we", "it", "bed",
                          "hat", "father", "boy", "show", "good", "moon", "how"})
      script.items.push_back({ScriptSection::kCommonWord, w, {}, "", 0.0});
    (void)record_reference_corpus(script, dir / "corpus", {.count = 0, .seed = 2, .script = {}},
                                  [&](const std::string& name, std::string_view bytes) {
                                    write_file_atomically(dir / "corpus" / name, bytes);
                                  });
    VoiceBuildOptions options;
    options.build_time_utc = "2026-12-02T00:00:00Z";
    options.tool_version = "test";
    options.corpus_name = "19 words, every viseme class (SYNTHETIC)";
    write_file_atomically(dir / "voice.fapv", build_voice(dir / "corpus", options).bytes);
    return dir / "voice.fapv";
  }();
  return file;
}

}  // namespace fapcast::test
