#include "live_session.hpp"

#include "live_client.hpp"
#include "synthesis_worker.hpp"

#include "fapcast/core/frame_rate.hpp"
#include "fapcast/face/facial_expression.hpp"
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/serve/live_message.hpp"
#include "fapcast/transport/timeline.hpp"

#include <algorithm>
#include <sstream>

namespace fapcast {
namespace {
using Clock = std::chrono::steady_clock;
using nlohmann::json;

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }
}  // namespace

std::string_view session_state_name(SessionState state) {
  switch (state) {
    case SessionState::kQueued: return "queued";
    case SessionState::kStarting: return "starting";
    case SessionState::kSpeaking: return "speaking";
    case SessionState::kDone: return "done";
    case SessionState::kStopped: return "stopped";
    case SessionState::kFailed: return "failed";
  }
  return "unknown";
}

LiveSession::LiveSession(SessionContext context, std::string id, std::uint32_t number, SayRequest request,
                         std::vector<RtpDestination> rtp, std::shared_ptr<const Speaker> speaker)
    : ctx_(std::move(context)),
      id_(std::move(id)),
      number_(number),
      request_(std::move(request)),
      sentences_(sentence_offsets(request_, ctx_.sentence_bytes)),
      destinations_(std::move(rtp)),
      speaker_(std::move(speaker)),
      encoder_(std::make_shared<FbaFrameEncoder>(FbaEncoderOptions{}, ctx_.rate)) {}

void LiveSession::start() {
  if (state_ != SessionState::kQueued) return;
  state_ = SessionState::kStarting;
  started_at_ = Clock::now();
  try {
    for (RtpDestination& d : destinations_) rtp_.push_back(std::make_unique<RtpSender>(ctx_.pacer.io(), d.endpoint, std::move(d.options), true));
  } catch (const std::exception& e) {
    // Not from inside start(): the server's caller may be iterating over the channel.
    rtp_.clear();
    asio::post(ctx_.io, [self = shared_from_this(), why = std::string(e.what())]() {
      if (self->state_ != SessionState::kStarting) return;
      if (self->ctx_.on_start_failed) self->ctx_.on_start_failed(500, "rtp-socket", why);
      self->end(SessionState::kFailed, "rtp-socket: " + why);
    });
    return;
  }
  submit(0);
}

void LiveSession::submit(std::size_t index) {
  if (index >= sentences_.size()) return;
  job_in_flight_ = true;
  const std::size_t from = sentences_[index];
  const std::size_t to = index + 1 < sentences_.size() ? sentences_[index + 1] : request_.text.size();
  SpeakerSettings settings;
  settings.speech.language = request_.lang;
  settings.speech.ssml = request_.ssml;
  settings.speech.source = "session " + id_ + " text";
  settings.rate = ctx_.rate;
  settings.expression = request_.expression;
  settings.name = "fapcast serve";
  ctx_.worker.submit(index == 0, [weak = weak_from_this(), cancelled = cancelled_, counted = ctx_.on_synthesised, io = &ctx_.io, voice = &ctx_.voice, speaker = speaker_,
                                  encoder = encoder_, settings = std::move(settings),
                                  source = "voice '" + ctx_.voice_name + "'", index,
                                  text = request_.text.substr(from, to - from)]() mutable {
    if (cancelled->load() || weak.expired()) return;  // the session ended while the job waited
    PreparedSentence p;
    p.index = index;
    p.text = std::move(text);
    try {
      if (!speaker) speaker = std::make_shared<const Speaker>(*voice, settings, source);
      p.speaker = speaker;
      p.spoken = speaker->speak(p.text);
      if (counted) counted();
      const SampleRate rate_hz = p.spoken.audio.sample_rate;
      FbaAccessUnit au;
      p.units.reserve(p.spoken.faps.frames.size());
      for (std::size_t k = 0; k < p.spoken.faps.frames.size(); ++k) {
        if (encoder->encode(p.spoken.faps.frames[k], au))
          throw std::runtime_error("fba-encode: " + encoder->error_detail());
        p.units.push_back({frame_to_sample(static_cast<std::int64_t>(k), settings.rate, rate_hz), std::move(au.bytes),
                           au.intra});
        au = {};
      }
    } catch (const std::exception& e) {
      p.error = e.what();
    }
    asio::post(*io, [weak, p = std::move(p)]() mutable {
      if (auto self = weak.lock()) self->on_prepared(std::move(p));
    });
  });
}

void LiveSession::on_prepared(PreparedSentence p) {
  job_in_flight_ = false;
  if (!active()) return;  // stopped while it was being synthesised
  if (p.error.empty() && !p.spoken.audio.sample_rate.valid()) p.error = "the front-end gave no audio";
  if (p.error.empty() && sample_rate_.valid() && p.spoken.audio.sample_rate != sample_rate_)
    p.error = "sentence " + std::to_string(p.index + 1) + " came at another audio rate";
  if (!p.error.empty()) {
    const std::string why = "synthesis-failed: sentence " + std::to_string(p.index + 1) + ": " + p.error;
    if (state_ == SessionState::kStarting && ctx_.on_start_failed) ctx_.on_start_failed(422, "synthesis-failed", why);
    end(SessionState::kFailed, why);
    return;
  }
  if (!speaker_) speaker_ = p.speaker;
  PacedSentence paced{nullptr, std::move(p.units)};
  paced.sentence = std::make_shared<const PreparedSentence>(std::move(p));
  ++handed_;
  if (state_ == SessionState::kStarting) {
    sample_rate_ = paced.sentence->spoken.audio.sample_rate;
    first_speech_time_ = paced.sentence->spoken.speech_time;
    first_animation_time_ = paced.sentence->spoken.animation_time;
    state_ = SessionState::kSpeaking;
    broadcast(session_message());
    // The first frame leaves now.
    stream_ = ctx_.pacer.open({weak_from_this(), std::move(rtp_), sample_rate_, ctx_.rate, ctx_.rtcp_interval, sentences_.size(),
                               Clock::now(), std::chrono::system_clock::now()},
                              std::move(paced));
    rtp_.clear();
    return;
  }
  ctx_.pacer.add(stream_, std::move(paced));
}

void LiveSession::on_sentence_begun(std::shared_ptr<const PreparedSentence> sentence, std::int64_t offset) {
  if (state_ != SessionState::kSpeaking) return;
  playing_ = std::move(sentence);
  playing_offset_ = offset;
  if (!ctx_.clients().empty()) broadcast(sentence_message(*playing_, offset));
  // One sentence ahead of the one being sent.
  if (!job_in_flight_ && handed_ == playing_->index + 1 && handed_ < sentences_.size()) submit(handed_);
}

void LiveSession::on_frame_sent(const PacedFrame& f) {
  if (state_ != SessionState::kSpeaking) return;  // its "end" went to the clients before this
  const PreparedSentence& s = *f.sentence;
  // Live clients: one message with the frame's weights and the audio shown with it.
  std::size_t messages = 0;
  const auto& clients = ctx_.clients();
  if (!clients.empty()) {
    std::vector<float> weights(static_cast<std::size_t>(s.spoken.weights.cols()));
    for (Eigen::Index c = 0; c < s.spoken.weights.cols(); ++c)
      weights[static_cast<std::size_t>(c)] = s.spoken.weights(static_cast<Eigen::Index>(f.frame), c);
    auto message = std::make_shared<std::string>();
    encode_live_frame(weights,
                      std::span(s.spoken.audio.samples).subspan(static_cast<std::size_t>(f.first), static_cast<std::size_t>(f.end - f.first)),
                      number_, f.sample, f.sequence, f.frame == 0, *message);
    for (const auto& c : clients) c->send(message, true), ++messages;
  }
  ++frames_sent_;
  if (messages > 0 && ctx_.on_live_messages) ctx_.on_live_messages(messages);
  if (frames_sent_ == 1) {
    first_frame_latency_ = f.sent - started_at_;
    if (ctx_.on_first_frame) ctx_.on_first_frame();
  }
}

void LiveSession::on_sentence_spoken(std::size_t) {
  if (state_ == SessionState::kSpeaking) ++sentences_spoken_;
}

void LiveSession::on_rtp_dropped(std::vector<std::string> why) {
  const std::size_t n = why.size();
  for (std::string& w : why) rtp_dropped_.push_back(std::move(w));
  if (ctx_.on_rtp_dropped) ctx_.on_rtp_dropped(n);
}

void LiveSession::on_stream_done() {
  if (state_ == SessionState::kSpeaking) end(SessionState::kDone, "done");
}

void LiveSession::stop(const std::string& reason) { end(SessionState::kStopped, reason); }

void LiveSession::end(SessionState state, const std::string& reason) {
  if (!active() && state_ != SessionState::kQueued) return;
  cancelled_->store(true);
  if (state_ == SessionState::kSpeaking) {
    // The pacer sends the closing reports (unless it has, at the end) and closes the sockets.
    ctx_.pacer.stop(stream_);
    broadcast(dump({{"type", "end"}, {"session", number_}, {"id", id_}, {"reason", reason}}));
  }
  state_ = state;
  reason_ = reason;
  rtp_.clear();  // its sockets close now, not when the record of the session goes
  stream_.reset();
  playing_.reset();
  if (ctx_.on_end) {
    auto on_end = std::move(ctx_.on_end);
    ctx_.on_end = nullptr;
    on_end();
  }
}

void LiveSession::broadcast(const std::string& text) const {
  const auto& clients = ctx_.clients();
  if (clients.empty()) return;
  const auto message = std::make_shared<const std::string>(text);
  for (const auto& c : clients) c->send(message, false);
}

std::string LiveSession::session_message() const {
  json expression = json::array();
  for (const Expression e : all_expressions()) {
    double w = 0;
    if (request_.expression) {
      if (request_.expression->first.expression == e) w += request_.expression->first.intensity / 63.0;
      if (request_.expression->second && request_.expression->second->expression == e)
        w += request_.expression->second->intensity / 63.0;
    }
    expression.push_back(std::min(w, 1.0));
  }
  return dump({{"type", "session"},
               {"session", number_},
               {"id", id_},
               {"channel", request_.channel},
               {"voice", request_.voice},
               {"sample_rate", sample_rate_.hz},
               {"fps", static_cast<double>(ctx_.rate.numerator) / ctx_.rate.denominator},
               {"components", speaker_ ? speaker_->components() : 0},
               {"expression_weights", expression},
               {"sentences", sentences_.size()}});
}

std::string LiveSession::sentence_message(const PreparedSentence& s, std::int64_t offset) const {
  json phones = json::array();
  for (const TimedPhone& p : s.spoken.phones)
    phones.push_back({std::string(arpabet(p.phone)), offset + p.start_sample, offset + p.end_sample});
  return dump({{"type", "sentence"},
               {"session", number_},
               {"index", s.index},
               {"sample", offset},
               {"samples", s.spoken.audio.instants()},
               {"frames", s.spoken.faps.frames.size()},
               {"text", s.text},
               {"phones", phones}});
}

void LiveSession::greet(LiveClient& client) const {
  if (state_ != SessionState::kSpeaking || !playing_) return;
  client.send(std::make_shared<const std::string>(session_message()), false);
  client.send(std::make_shared<const std::string>(sentence_message(*playing_, playing_offset_)), false);
}

nlohmann::json LiveSession::status() const {
  json j = {{"session", id_},
            {"state", session_state_name(state_)},
            {"channel", request_.channel},
            {"voice", request_.voice},
            {"sentences", sentences_.size()},
            {"sentences_spoken", sentences_spoken_},
            {"frames_sent", frames_sent_},
            {"rtp_destinations", destinations_.size()}};
  if (!rtp_dropped_.empty()) j["rtp_dropped"] = rtp_dropped_;
  if (!reason_.empty()) j["reason"] = reason_;
  if (frames_sent_ > 0) {
    j["first_frame_ms"] = std::chrono::duration<double, std::milli>(first_frame_latency_).count();
    j["first_sentence_speech_ms"] = std::chrono::duration<double, std::milli>(first_speech_time_).count();
    j["first_sentence_animation_ms"] = std::chrono::duration<double, std::milli>(first_animation_time_).count();
  }
  return j;
}

}  // namespace fapcast
