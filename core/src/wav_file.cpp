#include "fapcast/core/wav_file.hpp"

#include <sndfile.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "fapcast/core/file_io.hpp"

namespace fapcast {
namespace {

struct SndfileCloser {
  void operator()(SNDFILE* f) const { sf_close(f); }
};
using SndfilePtr = std::unique_ptr<SNDFILE, SndfileCloser>;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& rule, const std::string& detail) {
  throw InputError({path.string(), std::nullopt, std::nullopt}, rule, detail);
}

// RIFF/WAVE only: the data chunk must hold the bytes its header claims. libsndfile reads a
// truncated file silently as a shorter one (its log says "should be"); a cut-off recording is
// bad input. A size of 0 or 0xFFFFFFFF is a streaming writer's "unknown" and passes.
void check_wav_data_complete(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char riff[12];
  if (!in.read(riff, 12) || std::memcmp(riff, "RIFF", 4) != 0 || std::memcmp(riff + 8, "WAVE", 4) != 0)
    return;
  std::error_code ec;
  const std::uint64_t file_size = std::filesystem::file_size(path, ec);
  if (ec) return;
  std::uint64_t at = 12;
  for (int chunks = 0; chunks < 1024 && at + 8 <= file_size; ++chunks) {
    unsigned char header[8];
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(reinterpret_cast<char*>(header), 8)) return;
    const std::uint64_t size = header[4] | (header[5] << 8) | (header[6] << 16) |
                               (std::uint64_t{header[7]} << 24);
    if (std::memcmp(header, "data", 4) == 0) {
      const std::uint64_t held = file_size - at - 8;
      if (size != 0 && size != 0xffffffffu && size > held)
        throw InputError({path.string(), std::nullopt, at}, "wav-truncated",
                         "the data chunk claims " + std::to_string(size) + " bytes, the file holds " +
                             std::to_string(held));
      return;
    }
    at += 8 + size + (size & 1);  // chunks are padded to an even size
  }
}

// A growing byte buffer libsndfile writes into (its virtual I/O), so that the file itself is
// written once, atomically, by write_file_atomically.
struct MemoryFile {
  std::string bytes;
  sf_count_t position = 0;
};
sf_count_t memory_length(void* user) { return static_cast<sf_count_t>(static_cast<MemoryFile*>(user)->bytes.size()); }
sf_count_t memory_seek(sf_count_t offset, int whence, void* user) {
  auto& f = *static_cast<MemoryFile*>(user);
  const sf_count_t base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? f.position : static_cast<sf_count_t>(f.bytes.size());
  f.position = std::max<sf_count_t>(0, base + offset);
  return f.position;
}
sf_count_t memory_read(void* out, sf_count_t count, void* user) {
  auto& f = *static_cast<MemoryFile*>(user);
  const sf_count_t size = static_cast<sf_count_t>(f.bytes.size());
  const sf_count_t n = std::clamp<sf_count_t>(size - f.position, 0, count);
  if (n > 0) std::memcpy(out, f.bytes.data() + f.position, static_cast<std::size_t>(n));
  f.position += n;
  return n;
}
sf_count_t memory_write(const void* in, sf_count_t count, void* user) {
  auto& f = *static_cast<MemoryFile*>(user);
  const auto end = static_cast<std::size_t>(f.position + count);
  if (end > f.bytes.size()) f.bytes.resize(end);
  std::memcpy(f.bytes.data() + f.position, in, static_cast<std::size_t>(count));
  f.position += count;
  return count;
}
sf_count_t memory_tell(void* user) { return static_cast<MemoryFile*>(user)->position; }

}  // namespace

Audio read_wav(const std::filesystem::path& path, std::int64_t max_instants) {
  SF_INFO info{};
  SndfilePtr file(sf_open(path.c_str(), SFM_READ, &info));
  if (!file) fail(path, "wav-open", std::string("cannot read as audio: ") + sf_strerror(nullptr));
  if (info.channels < 1 || info.channels > 1024) fail(path, "wav-channels", "unsupported channel count");
  if (info.samplerate < 1) fail(path, "wav-rate", "sample rate must be positive");
  check_wav_data_complete(path);
  Audio audio;
  audio.sample_rate = SampleRate{info.samplerate};
  audio.channels = info.channels;
  constexpr sf_count_t kChunkInstants = 4096;
  std::vector<std::int16_t> chunk(static_cast<std::size_t>(kChunkInstants) * info.channels);
  for (;;) {
    const sf_count_t got = sf_readf_short(file.get(), chunk.data(), kChunkInstants);
    if (got <= 0) break;
    if (audio.instants() + got > max_instants)
      fail(path, "wav-too-long", "more than " + std::to_string(max_instants) + " sampling instants");
    audio.samples.insert(audio.samples.end(), chunk.begin(),
                         chunk.begin() + static_cast<std::ptrdiff_t>(got * info.channels));
  }
  if (sf_error(file.get()) != SF_ERR_NO_ERROR) fail(path, "wav-read", sf_strerror(file.get()));
  return audio;
}

Audio read_mono_wav(const std::filesystem::path& path, std::int64_t max_instants) {
  Audio audio = read_wav(path, max_instants);
  if (audio.channels != 1)
    fail(path, "wav-mono", "expected mono audio, found " + std::to_string(audio.channels) + " channels");
  return audio;
}

std::string wav_bytes(const Audio& audio) {
  if (audio.sample_rate.hz < 1 || audio.sample_rate.hz > 0x7fffffff)
    throw std::invalid_argument("WAV: sample rate " + std::to_string(audio.sample_rate.hz) + " Hz out of range");
  if (audio.channels < 1) throw std::invalid_argument("WAV: channel count must be positive");
  SF_VIRTUAL_IO io{memory_length, memory_seek, memory_read, memory_write, memory_tell};
  MemoryFile memory;
  SF_INFO info{};
  info.samplerate = static_cast<int>(audio.sample_rate.hz);
  info.channels = audio.channels;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  {
    SndfilePtr file(sf_open_virtual(&io, SFM_WRITE, &info, &memory));
    if (!file) throw std::runtime_error(std::string("WAV: cannot encode: ") + sf_strerror(nullptr));
    const sf_count_t n = audio.instants();
    if (sf_writef_short(file.get(), audio.samples.data(), n) != n)
      throw std::runtime_error(std::string("WAV: write failed: ") + sf_strerror(file.get()));
  }
  return std::move(memory.bytes);
}

namespace {

// libsndfile's virtual file over an AtomicFile: appends at the end, writes back (the header)
// anywhere before it. Nothing is read back.
struct AtomicSink {
  AtomicFile* file;
  sf_count_t position = 0;
  sf_count_t length = 0;
  std::exception_ptr error;  // what the AtomicFile threw (not through libsndfile's C frames)
};
sf_count_t sink_length(void* user) { return static_cast<AtomicSink*>(user)->length; }
sf_count_t sink_seek(sf_count_t offset, int whence, void* user) {
  auto& f = *static_cast<AtomicSink*>(user);
  const sf_count_t base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? f.position : f.length;
  f.position = std::max<sf_count_t>(0, base + offset);
  return f.position;
}
sf_count_t sink_read(void*, sf_count_t, void*) { return 0; }
sf_count_t sink_write(const void* in, sf_count_t count, void* user) {
  auto& f = *static_cast<AtomicSink*>(user);
  const std::string_view bytes(static_cast<const char*>(in), static_cast<std::size_t>(count));
  try {
    // Always at the sink's own position: a pwrite does not move the descriptor's offset, so a
    // later appending write() after one that ran past the end would land inside it.
    f.file->write_at(static_cast<std::uint64_t>(f.position), bytes);
  } catch (...) {
    f.error = std::current_exception();
    return 0;
  }
  f.position += count;
  f.length = std::max(f.length, f.position);
  return count;
}
sf_count_t sink_tell(void* user) { return static_cast<AtomicSink*>(user)->position; }

}  // namespace

struct WavWriter::State {
  AtomicSink sink;
  SF_VIRTUAL_IO io{sink_length, sink_seek, sink_read, sink_write, sink_tell};
  SndfilePtr file;
};

WavWriter::WavWriter(AtomicFile& file, SampleRate rate) : state_(std::make_unique<State>()) {
  if (rate.hz < 1 || rate.hz > 0x7fffffff)
    throw std::invalid_argument("WAV: sample rate " + std::to_string(rate.hz) + " Hz out of range");
  state_->sink.file = &file;
  SF_INFO info{};
  info.samplerate = static_cast<int>(rate.hz);
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  state_->file.reset(sf_open_virtual(&state_->io, SFM_WRITE, &info, &state_->sink));
  if (!state_->file) throw std::runtime_error(file.path().string() + ": WAV: cannot encode: " + sf_strerror(nullptr));
}

WavWriter::~WavWriter() = default;

void WavWriter::append(std::span<const std::int16_t> samples) {
  if (!state_->file) throw std::logic_error("WavWriter::append after finish");
  const auto n = static_cast<sf_count_t>(samples.size());
  // The RIFF and data chunk sizes are 32-bit (libsndfile would wrap them silently).
  constexpr std::int64_t kMaxDataBytes = 0xFFFFFFFFLL - 44;
  if (2 * (instants_ + n) > kMaxDataBytes)
    throw std::runtime_error(state_->sink.file->path().string() +
                             ": WAV: more than 4 GiB of 16-bit samples, past the RIFF header's 32-bit sizes");
  if (sf_writef_short(state_->file.get(), samples.data(), n) != n) {
    if (state_->sink.error) std::rethrow_exception(state_->sink.error);
    throw std::runtime_error(state_->sink.file->path().string() + ": WAV: write failed: " + sf_strerror(state_->file.get()));
  }
  instants_ += n;
}

void WavWriter::finish() {
  if (!state_->file) return;
  const int closed = sf_close(state_->file.release());  // writes the header's lengths
  if (state_->sink.error) std::rethrow_exception(state_->sink.error);
  if (closed != 0)
    throw std::runtime_error(state_->sink.file->path().string() + ": WAV: cannot finish: " + sf_error_number(closed));
}

void write_wav(const std::filesystem::path& path, const Audio& audio) {
  write_file_atomically(path, wav_bytes(audio));
}

}  // namespace fapcast
