#pragma once
// Sound files through libsndfile: WAV and every other format it reads (any PCM or float
// encoding, any rate and channel count, converted to 16-bit), and 16-bit PCM WAV written
// atomically.
#include "fapcast/core/audio.hpp"
#include "fapcast/core/input_error.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

namespace fapcast {

// Longest audio read_wav accepts by default: 2^31 sampling instants (13.5 hours at 44.1 kHz).
inline constexpr std::int64_t kMaxWavInstants = std::int64_t{1} << 31;

// Reads a whole sound file, every channel. Throws InputError naming the file and the rule:
// wav-open (not a sound file libsndfile reads), wav-channels (none, or more than 1024), wav-rate
// (not positive), wav-too-long (more than `max_instants` sampling instants), wav-read (a read
// error part way), wav-truncated (a RIFF/WAVE data chunk shorter than its header says, at the
// chunk's byte offset). Reads in chunks and never allocates from the header's claimed length.
Audio read_wav(const std::filesystem::path& path, std::int64_t max_instants = kMaxWavInstants);

// read_wav, refusing audio of more than one channel (rule wav-mono): speech to animate.
Audio read_mono_wav(const std::filesystem::path& path, std::int64_t max_instants = kMaxWavInstants);

// The bytes of a 16-bit PCM WAV file of `audio` (any channel count). Throws std::invalid_argument
// for a rate below 1 or a channel count below 1, std::runtime_error when libsndfile fails.
std::string wav_bytes(const Audio& audio);

class AtomicFile;

// A 16-bit PCM mono WAV written piece by piece into an AtomicFile's temporary file: the samples
// go out as they come (libsndfile writes the header first and patches its lengths in finish()),
// so a long text's speech is never held whole. The bytes equal wav_bytes() of all the pieces
// together. The caller commits the file after finish().
class WavWriter {
 public:
  // Throws std::invalid_argument for a rate out of 1..2^31-1, std::runtime_error when
  // libsndfile fails.
  WavWriter(AtomicFile& file, SampleRate rate);
  ~WavWriter();
  WavWriter(const WavWriter&) = delete;
  WavWriter& operator=(const WavWriter&) = delete;
  void append(std::span<const std::int16_t> samples);
  // Closes the WAV: its header's lengths written. Appending after it throws std::logic_error.
  void finish();
  std::int64_t instants() const { return instants_; }

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::int64_t instants_ = 0;
};

// Writes wav_bytes(audio) to `path` atomically (write_file_atomically). Throws as they do.
void write_wav(const std::filesystem::path& path, const Audio& audio);

}  // namespace fapcast
