#include "fapcast/cues/mouth_cues.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <string>

namespace fapcast {

namespace {

using S = MouthShape;

constexpr Centiseconds cs(std::int64_t n) { return Centiseconds{n}; }

// For each shape, every shape in the order of the effort to move there from it (Rhubarb's
// table; spec/mouth-cues.md, "Choosing among allowed shapes"). Rows in enum order.
constexpr std::array<std::array<S, kMouthShapeCount>, kMouthShapeCount> kEffortOrder{{
    {S::A, S::X, S::G, S::B, S::C, S::H, S::E, S::D, S::F},
    {S::B, S::G, S::A, S::X, S::C, S::H, S::E, S::D, S::F},
    {S::C, S::H, S::B, S::G, S::D, S::A, S::X, S::E, S::F},
    {S::D, S::C, S::H, S::B, S::G, S::A, S::X, S::E, S::F},
    {S::E, S::C, S::H, S::B, S::G, S::A, S::X, S::D, S::F},
    {S::F, S::B, S::G, S::A, S::X, S::C, S::H, S::E, S::D},
    {S::G, S::A, S::B, S::C, S::H, S::X, S::E, S::D, S::F},
    {S::H, S::C, S::B, S::G, S::D, S::A, S::X, S::E, S::F},
    {S::X, S::A, S::G, S::B, S::C, S::H, S::E, S::D, S::F},
}};

// The shape the mouth relaxes to from each (enum order): open shapes close by a step.
constexpr std::array<S, kMouthShapeCount> kRelaxed{S::A, S::B, S::B, S::C, S::C, S::B, S::X, S::B, S::X};

constexpr S relaxed(S s) { return kRelaxed[static_cast<std::size_t>(s)]; }

// The allowed shape that takes the least effort to reach from `from`.
S closest(S from, MouthShapeSet allowed) {
  for (S s : kEffortOrder[static_cast<std::size_t>(from)])
    if (allowed.contains(s)) return s;
  throw std::logic_error("mouth_cues: a phone allows no shape");
}

// How a phone's allowed shapes are laid over its span.
enum class Timing : std::uint8_t {
  kSingle,     // `first` over the whole phone
  kDiphthong,  // `first` over its first 60 %, `second` over the rest
  kPlosive,    // `first` for the closure just before the phone, `second` over the phone
};

struct PhoneRule {
  Timing timing;
  MouthShapeSet first;
  MouthShapeSet second;
};

const MouthShapeSet kAny = MouthShapeSet::all();
const MouthShapeSet kAnyOpen{S::B, S::C, S::D, S::E, S::F, S::G, S::H};

PhoneRule single(MouthShapeSet s) { return {Timing::kSingle, s, {}}; }
PhoneRule diphthong(S a, S b) { return {Timing::kDiphthong, {a}, {b}}; }
PhoneRule plosive(MouthShapeSet closure, MouthShapeSet release) { return {Timing::kPlosive, closure, release}; }

// The rule of each phone of `length` (spec/mouth-cues.md, "Phones to shapes").
PhoneRule phone_rule(Phone p, Centiseconds length) {
  switch (p) {
    case Phone::AA: return single({S::D});
    case Phone::AE: return single({S::C});
    case Phone::AH: return single({length < cs(20) ? S::C : S::D});
    case Phone::AO: return single({S::E});
    case Phone::AW: return length < cs(30) ? diphthong(S::C, S::E) : diphthong(S::D, S::E);
    case Phone::AX: return single({S::B, S::C});
    case Phone::AY: return length < cs(20) ? diphthong(S::C, S::B) : diphthong(S::D, S::B);
    case Phone::EH: return single({S::C});
    case Phone::ER: return length < cs(7) ? single({S::B, S::C}) : single({S::E});
    case Phone::EY: return diphthong(S::C, S::B);
    case Phone::IH: return single({S::B});
    case Phone::IY: return single({S::B});
    case Phone::OW: return diphthong(S::E, S::F);
    case Phone::OY: return diphthong(S::E, S::B);
    case Phone::UH: return single({S::F});
    case Phone::UW: return single({S::F});
    case Phone::B:
    case Phone::P: return plosive({S::A}, kAny);
    case Phone::D:
    case Phone::T: return plosive({S::B, S::F}, kAnyOpen);
    case Phone::G:
    case Phone::K: return plosive({S::B, S::C, S::E, S::F, S::H}, kAnyOpen);
    case Phone::CH:
    case Phone::JH: return single({S::B, S::F});
    case Phone::F:
    case Phone::V: return single({S::G});
    case Phone::DH:
    case Phone::TH:
    case Phone::S:
    case Phone::Z:
    case Phone::SH:
    case Phone::ZH: return single({S::B, S::F});
    case Phone::HH: return single(kAny);
    case Phone::M: return single({S::A});
    case Phone::N: return single({S::B, S::C, S::F, S::H});
    case Phone::NG: return single({S::B, S::C, S::E, S::F});
    case Phone::L: return length < cs(20) ? single({S::B, S::E, S::F, S::H}) : single({S::H});
    case Phone::R: return single({S::B, S::E, S::F});
    case Phone::W: return single({S::F});
    case Phone::Y: return single({S::B, S::C, S::F});
    case Phone::SIL: return single({S::X});
  }
  throw std::logic_error("mouth_cues: phone without a rule");
}

// A stretch of the timeline and the shapes allowed there.
struct Rule {
  Centiseconds start;
  Centiseconds end;
  MouthShapeSet allowed;
  bool vowel = false;  // a vowel's (anticipated when it allows one shape)
};

// Lays `piece` over `spans` (contiguous, in order), cutting what it covers. `piece` must lie near
// the end of `spans`: the search for what it covers starts from the back.
template <typename Span>
void lay(std::vector<Span>& spans, Span piece) {
  if (piece.end <= piece.start) return;
  std::size_t i = spans.size();
  while (i > 0 && spans[i - 1].end > piece.start) --i;
  std::vector<Span> tail(spans.begin() + static_cast<std::ptrdiff_t>(i), spans.end());
  spans.resize(i);
  if (!tail.empty() && tail.front().start < piece.start) {
    Span left = tail.front();
    left.end = piece.start;
    spans.push_back(left);
  }
  spans.push_back(piece);
  for (const Span& old : tail) {
    if (old.end <= piece.end) continue;
    Span right = old;
    right.start = std::max(old.start, piece.end);
    spans.push_back(right);
  }
}

// `cues` with empty cues dropped and equal neighbours joined.
std::vector<MouthCue> joined(const std::vector<MouthCue>& cues) {
  std::vector<MouthCue> out;
  for (const MouthCue& c : cues) {
    if (c.end <= c.start) continue;
    if (!out.empty() && out.back().shape == c.shape) {
      out.back().end = c.end;
      continue;
    }
    out.push_back(c);
  }
  return out;
}

MouthShapeSet shown_set(MouthShapeSet allowed, MouthShapeSet drawn) {
  MouthShapeSet out;
  for (const MouthShapeInfo& row : kMouthShapeTable)
    if (allowed.contains(row.shape)) out.insert(shown_shape(row.shape, drawn));
  return out;
}

// The rules of `phones` over [0, duration): a pause wherever no phone is.
std::vector<Rule> phone_rules(std::span<const TimedPhone> phones, SampleRate rate, Centiseconds duration,
                              MouthShapeSet drawn) {
  // X stays in the rules until the end (Rhubarb's rule): the pause rules act on it, and only the
  // final cues show it as A when the drawings lack it.
  MouthShapeSet drawn_and_x = drawn;
  drawn_and_x.insert(S::X);
  const MouthShapeSet pause{S::X};
  std::vector<Rule> rules{{cs(0), duration, pause, false}};
  Centiseconds previous_start = cs(0);  // where the stretch before the current phone began
  Centiseconds previous_end = cs(0);
  std::int64_t last_end_sample = 0;
  for (std::size_t i = 0; i < phones.size(); ++i) {
    const TimedPhone& p = phones[i];
    if (p.end_sample < p.start_sample || p.start_sample < last_end_sample)
      throw std::invalid_argument("mouth_cues: phone " + std::to_string(i) + " is out of order or overlaps the one before");
    last_end_sample = p.end_sample;
    const Centiseconds start = std::min(truncated_centiseconds(p.start_sample, rate), duration);
    const Centiseconds end = std::min(truncated_centiseconds(p.end_sample, rate), duration);
    if (end <= start || p.phone == Phone::SIL) continue;
    // The stretch before: the phone before when it ends here, else the pause since it ended.
    const Centiseconds before = previous_end == start ? start - previous_start : start - previous_end;
    previous_start = start;
    previous_end = end;
    const PhoneRule rule = phone_rule(p.phone, end - start);
    const bool vowel = is_vowel(p.phone);
    const MouthShapeSet first = shown_set(rule.first, drawn_and_x), second = shown_set(rule.second, drawn_and_x);
    switch (rule.timing) {
      case Timing::kSingle:
        lay(rules, Rule{start, end, first, vowel});
        break;
      case Timing::kDiphthong: {
        const Centiseconds middle = start + (end - start) * 6 / 10;
        lay(rules, Rule{start, middle, first, vowel});
        lay(rules, Rule{middle, end, second, vowel});
        break;
      }
      case Timing::kPlosive: {
        const Centiseconds closure = std::clamp(before / 2, cs(4), cs(12));
        lay(rules, Rule{std::max(start - closure, cs(0)), start, first, false});
        lay(rules, Rule{start, end, second, false});
        break;
      }
    }
  }
  return rules;
}

// One shape per rule: forwards, each the allowed shape nearest the relaxed shape before it; a
// vowel with one allowed shape is anticipated, spreading back over up to 20 cs of the rules
// before it while they can show a shape like it.
std::vector<MouthCue> rough_animation(const std::vector<Rule>& rules) {
  std::vector<S> shapes(rules.size(), S::X);
  S reference = S::X;
  std::optional<Centiseconds> last_anticipated;
  for (std::size_t i = 0; i < rules.size(); ++i) {
    const S shape = closest(reference, rules[i].allowed);
    shapes[i] = shape;
    const bool anticipate = rules[i].vowel && rules[i].allowed.size() == 1;
    if (anticipate) {
      S towards = shape;
      for (std::size_t j = i; j > 0; --j) {
        const Rule& r = rules[j - 1];
        if (last_anticipated && r.start == *last_anticipated) break;
        if (rules[i].start - r.start > cs(20)) break;
        shapes[j - 1] = closest(towards, r.allowed);
        if (mouth_shape_info(shapes[j - 1]).basic != mouth_shape_info(shape).basic) break;
        towards = shapes[j - 1];
      }
      last_anticipated = rules[i].start;
    }
    reference = anticipate ? shape : relaxed(shape);
  }
  std::vector<MouthCue> cues;
  cues.reserve(rules.size());
  for (std::size_t i = 0; i < rules.size(); ++i) cues.push_back({shapes[i], rules[i].start, rules[i].end});
  return joined(cues);
}

// The shape of a pause of `length` between `before` and `after`: a short one holds the shape
// before, a middling one relaxes it (to a shape unlike the next), a long one rests the mouth.
S pause_shape(S before, S after, Centiseconds length) {
  if (length < cs(12)) return before;
  if (length <= cs(35)) {
    for (S s = before;;) {
      const S r = relaxed(s);
      if (r != after) return r;
      if (r == s) break;
      s = r;
    }
  }
  return S::X;
}

std::vector<MouthCue> animate_pauses(const std::vector<MouthCue>& cues) {
  std::vector<MouthCue> out = cues;
  for (std::size_t i = 1; i + 1 < cues.size(); ++i)
    if (cues[i].shape == S::X) out[i].shape = pause_shape(cues[i - 1].shape, cues[i + 1].shape, cues[i].end - cues[i].start);
  return joined(out);
}

enum class TweenTiming : std::uint8_t { kEarly, kCentered, kLate };

struct Tween {
  S from, to, between;
  TweenTiming timing;
};

// The in-betweens (spec/mouth-cues.md, "In-betweens"): mostly on the way closed, since a mouth
// pops open and closes slowly.
constexpr std::array<Tween, 9> kTweens{{
    {S::D, S::A, S::C, TweenTiming::kEarly},
    {S::D, S::B, S::C, TweenTiming::kCentered},
    {S::D, S::G, S::C, TweenTiming::kEarly},
    {S::D, S::X, S::C, TweenTiming::kLate},
    {S::C, S::F, S::E, TweenTiming::kCentered},
    {S::F, S::C, S::E, TweenTiming::kCentered},
    {S::D, S::F, S::E, TweenTiming::kCentered},
    {S::H, S::F, S::E, TweenTiming::kLate},
    {S::F, S::H, S::E, TweenTiming::kEarly},
}};

std::vector<MouthCue> insert_tweens(const std::vector<MouthCue>& cues) {
  std::vector<MouthCue> out;
  out.reserve(cues.size() * 2);
  for (std::size_t i = 0; i < cues.size(); ++i) {
    out.push_back(cues[i]);
    if (i == 0) continue;
    const MouthCue& a = cues[i - 1];
    const MouthCue& b = cues[i];
    const auto t = std::find_if(kTweens.begin(), kTweens.end(),
                                [&](const Tween& w) { return w.from == a.shape && w.to == b.shape; });
    if (t == kTweens.end()) continue;
    const Centiseconds la = a.end - a.start, lb = b.end - b.start;
    Centiseconds length{0}, start{0};
    switch (t->timing) {
      case TweenTiming::kEarly:
        length = std::min(la / 3, cs(8));
        start = a.end - length;
        break;
      case TweenTiming::kCentered:
        length = std::min({la / 4, lb / 4, cs(8)});
        start = a.end - length / 2;
        break;
      case TweenTiming::kLate:
        length = std::min(lb / 3, cs(8));
        start = b.start;
        break;
    }
    if (length < cs(4)) continue;
    lay(out, MouthCue{t->between, start, start + length});
  }
  return joined(out);
}

}  // namespace

Centiseconds truncated_centiseconds(std::int64_t sample, SampleRate rate) {
  if (!rate.valid()) throw std::invalid_argument("mouth_cues: sample rate must be positive");
  return Centiseconds{sample * 100 / rate.hz};
}

std::vector<MouthCue> mouth_cues(std::span<const TimedPhone> phones, SampleRate rate, std::int64_t audio_samples,
                                 const MouthCueOptions& options) {
  const Centiseconds duration = truncated_centiseconds(std::max<std::int64_t>(audio_samples, 0), rate);
  if (duration <= cs(0)) return {};
  const std::vector<Rule> rules = phone_rules(phones, rate, duration, options.drawn);
  std::vector<MouthCue> cues = insert_tweens(animate_pauses(rough_animation(rules)));
  for (MouthCue& c : cues) c.shape = shown_shape(c.shape, options.drawn);
  return joined(cues);
}

}  // namespace fapcast
