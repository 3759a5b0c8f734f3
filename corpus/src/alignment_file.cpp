#include "fapcast/corpus/alignment_file.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/lab_file.hpp"
#include "fapcast/corpus/bas_partitur.hpp"
#include "fapcast/corpus/esps_label.hpp"
#include "fapcast/corpus/gentle_json.hpp"
#include "fapcast/corpus/htk_mlf.hpp"
#include "fapcast/corpus/timit_label.hpp"
#include "fapcast/corpus/textgrid.hpp"
#include "fapcast/core/text_input.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fapcast {
namespace {


[[noreturn]] void refuse(const std::string& source, const std::string& rule, const std::string& detail) {
  throw InputError({source, std::nullopt, std::nullopt}, rule, detail);
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

std::string extension_of(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = name.rfind('.');
  return dot == std::string::npos ? "" : lower(name.substr(dot));
}

std::string stem_of(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = name.rfind('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 0.1 ? "%.1f ms" : "%.2f s", s < 0.1 ? s * 1000 : s);
  return buf;
}

std::string with_article(std::string_view name) {
  return (std::string_view("AEIOU").find(name.front()) != std::string_view::npos ? "an " : "a ") + std::string(name);
}

std::string percent(double f) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.1f %%", f * 100);
  return buf;
}

// The format the content shows, from its first bytes and first lines.
AlignmentFormat sniff(std::string_view bytes, const std::string& source) {
  if (bytes.starts_with("ooBinaryFile") || bytes.starts_with("ooBinary2File")) return AlignmentFormat::textgrid;
  // Structure is ASCII: look at the bytes as they are, decoded only when a byte-order mark
  // says UTF-16 (Praat's UTF-16 TextGrids); each reader checks the encoding itself.
  std::string text(bytes.substr(0, std::min<std::size_t>(bytes.size(), std::size_t{1} << 16)));
  if (bytes.starts_with("\xFF\xFE") || bytes.starts_with("\xFE\xFF")) text = decode_text(bytes, source, "alignment");
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
  const auto lines = split_lines(text);
  std::size_t first = 0;
  while (first < lines.size() && trim(lines[first].text).empty()) ++first;
  if (first == lines.size()) refuse(source, "alignment-empty", "the file has no content");
  const std::string_view head = trim(lines[first].text);
  if (head.starts_with("File type = \"ooTextFile") || head == "\"Praat chronological TextGrid text file\"") {
    return AlignmentFormat::textgrid;
  }
  if (head == "#!MLF!#") return AlignmentFormat::mlf;
  for (const char* key : {"signal ", "separator ", "seperator ", "nfields ", "type ", "color ", "comment "}) {
    if (head.starts_with(key)) return AlignmentFormat::esps;  // an xlabel header line
  }
  if (head.starts_with('{') || head.starts_with('[')) return AlignmentFormat::gentle;
  if (head.size() >= 4 && head[3] == ':' &&
      std::all_of(head.begin(), head.begin() + 3, [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); })) {
    return AlignmentFormat::partitur;
  }
  for (std::size_t i = first; i < lines.size() && i < first + 64; ++i) {
    if (trim(lines[i].text) == "#") return AlignmentFormat::esps;
  }
  const auto f = split_whitespace(head);
  std::int64_t n = 0;
  if (f.size() >= 3 && parse_count(f[0], n) && parse_count(f[1], n)) return AlignmentFormat::htk_lab;
  return AlignmentFormat::seconds_lab;
}

bool extension_agrees(AlignmentFormat f, const std::string& ext) {
  switch (f) {
    case AlignmentFormat::textgrid: return ext == ".textgrid";
    case AlignmentFormat::mlf: return ext == ".mlf";
    case AlignmentFormat::partitur: return ext == ".par";
    case AlignmentFormat::gentle: return ext == ".json";
    case AlignmentFormat::timit: return ext == ".phn" || ext == ".wrd";
    case AlignmentFormat::htk_lab:
    case AlignmentFormat::seconds_lab:
    case AlignmentFormat::esps: return ext == ".lab" || ext == ".rec" || ext == ".seg" || ext == ".phones";
  }
  return false;
}

// Extensions that promise a format; others (".txt", none) leave it to the content.
bool extension_promises(const std::string& ext) {
  return ext == ".textgrid" || ext == ".mlf" || ext == ".par" || ext == ".json" || ext == ".phn" || ext == ".wrd" ||
         ext == ".lab" || ext == ".rec";
}

// Integer rows: HTK 100 ns units or TIMIT samples? The extension says which is meant; the
// numbers, against the recording, say which it is. Refused when they disagree.
void check_integer_units(const LabelTier& as_read, AlignmentFormat format, const std::string& source,
                         const AlignmentFileOptions& o) {
  if (as_read.intervals.empty()) return;
  const double end = as_read.intervals.back().end_s;  // in the unit the extension meant
  const double ticks = format == AlignmentFormat::timit ? end * static_cast<double>(o.sample_rate->hz) : end * 1e7;
  const auto plausible = [](double covered) { return covered >= 0.5 && covered <= 1.05; };
  if (o.audio_seconds && *o.audio_seconds > 0) {
    const double as_htk = ticks * 1e-7, as_samples = o.sample_rate ? ticks / static_cast<double>(o.sample_rate->hz) : -1;
    const double audio = *o.audio_seconds;
    if (format == AlignmentFormat::htk_lab && !plausible(as_htk / audio) && plausible(as_samples / audio)) {
      refuse(source, "lab-units-mismatch",
             "as HTK 100 ns units (what a .lab holds) the segments end at " + seconds(as_htk) + " of a " +
                 seconds(audio) + " recording; as samples at " + std::to_string(o.sample_rate->hz) + " Hz they end at " +
                 seconds(as_samples) + ": this is a TIMIT-style file of sample offsets, name it .phn (or .wrd)");
    }
    if (format == AlignmentFormat::timit && !plausible(as_samples / audio) && plausible(as_htk / audio)) {
      refuse(source, "lab-units-mismatch",
             "as samples at " + std::to_string(o.sample_rate->hz) + " Hz (what a .phn holds) the segments end at " +
                 seconds(as_samples) + " of a " + seconds(audio) + " recording; as HTK 100 ns units at " +
                 seconds(as_htk) + ": this is an HTK label file, name it .lab");
    }
  } else if (format == AlignmentFormat::htk_lab) {
    const double mean = end / static_cast<double>(as_read.intervals.size());
    if (mean < 0.005) {
      refuse(source, "lab-units-mismatch",
             "as HTK 100 ns units its " + std::to_string(as_read.intervals.size()) + " segments average " +
                 seconds(mean) + " (no phone is that short): sample offsets? name the file .phn and give the recording");
    }
  }
}

struct Choice {
  const LabelTier* tier = nullptr;
  std::string why;
};

std::string tier_list(const std::vector<const LabelTier*>& tiers) {
  std::string s;
  for (const LabelTier* t : tiers) s += (s.empty() ? "\"" : ", \"") + t->name + "\"";
  return s;
}

// How many of the tier's non-silence labels `set` maps, and the first it does not.
struct Score {
  std::size_t mapped = 0, total = 0;
  std::optional<std::size_t> first_unknown;
  double fraction() const { return total == 0 ? 0 : static_cast<double>(mapped) / static_cast<double>(total); }
};
Score score(const LabelTier& t, LabelSet set) {
  Score s;
  for (std::size_t i = 0; i < t.intervals.size(); ++i) {
    if (common_non_phone(t.intervals[i].label)) continue;
    ++s.total;
    if (map_label(set, t.intervals[i].label)) {
      ++s.mapped;
    } else if (!s.first_unknown) {
      s.first_unknown = i;
    }
  }
  return s;
}
std::pair<LabelSet, Score> best_set(const LabelTier& t) {
  std::pair<LabelSet, Score> best{LabelSet::arpabet, score(t, LabelSet::arpabet)};
  for (LabelSet s : kLabelSets) {
    const Score sc = score(t, s);
    if (sc.fraction() > best.second.fraction()) best = {s, sc};
  }
  return best;
}

// The names that mark a phone tier, strongest first: MFA/Praat/EMU/MAUS names, then a
// speaker's phone tier (MFA "speaker - phones", FAVE "speaker - phone"), then phonemic tiers.
int name_rank(std::string_view name) {
  const std::string n = lower(name);
  for (const char* s : {"phones", "phone", "phonetic", "mau", "segments", "phn"}) {
    if (n == s) return 1;
  }
  if (n.ends_with(" - phones") || n.ends_with(" - phone")) return 2;
  for (const char* s : {"phonemes", "phoneme"}) {
    if (n == s) return 3;
  }
  return 0;
}

Choice choose_tier(const Alignment& a, const std::string& source, const AlignmentFileOptions& o) {
  std::vector<const LabelTier*> intervals;
  for (const LabelTier& t : a.tiers) {
    if (t.kind == TierKind::intervals) intervals.push_back(&t);
  }
  if (o.tier) {
    for (const LabelTier* t : intervals) {
      if (t->name == *o.tier) return {t, "named by the user"};
    }
    refuse(source, "alignment-no-such-tier", "no interval tier \"" + excerpt(*o.tier) + "\"; it has " +
                                                 (intervals.empty() ? std::string("none") : tier_list(intervals)));
  }
  if (intervals.size() == 1 && a.tiers.size() == 1) {
    const Score sc = best_set(*intervals[0]).second;
    if (name_rank(intervals[0]->name) == 0 && sc.total > 0 && sc.fraction() < 0.95) {
      refuse(source, "alignment-no-phone-tier",
             "its only tier, \"" + intervals[0]->name + "\", holds no phones (\"" +
                 excerpt(intervals[0]->intervals[*sc.first_unknown].label) + "\" ...): a transcript, not an alignment?");
    }
    return {intervals[0], "the only tier"};
  }
  for (int rank = 1; rank <= 3; ++rank) {
    std::vector<const LabelTier*> hits;
    for (const LabelTier* t : intervals) {
      if (name_rank(t->name) == rank) hits.push_back(t);
    }
    if (hits.size() == 1) return {hits[0], "by its name"};
    if (hits.size() > 1) {
      refuse(source, "alignment-tier-ambiguous",
             std::to_string(hits.size()) + " phone tiers (" + tier_list(hits) + "): name one with --tier");
    }
  }
  // No tier has a phone tier's name: the one whose labels a label set maps entirely.
  std::vector<const LabelTier*> mapped;
  for (const LabelTier* t : intervals) {
    const Score s = best_set(*t).second;
    if (s.total > 0 && s.mapped == s.total) mapped.push_back(t);
  }
  if (mapped.size() == 1) return {mapped[0], "by its labels (no tier is named phones)"};
  if (mapped.size() > 1) {
    refuse(source, "alignment-tier-ambiguous",
           "no tier is named phones and the labels of " + tier_list(mapped) + " all read as phones: name one with --tier");
  }
  refuse(source, "alignment-no-phone-tier",
         "no tier is named phones and none has labels that read as phones; it has " + tier_list(intervals));
}

std::string label_set_article(LabelSet set) {
  switch (set) {
    case LabelSet::arpabet: return "an ARPAbet";
    case LabelSet::timit: return "a TIMIT";
    case LabelSet::ipa: return "an IPA";
    case LabelSet::sampa: return "a SAMPA";
    case LabelSet::emu_ae: return "an EMU ae";
    case LabelSet::mocha: return "a MOCHA-TIMIT";
  }
  return "a";
}

// HTS full-context labels ("x^pau-hh+iy=t@1_2/A:...") name the phone between '-' and '+';
// state-aligned files add "[2]".."[6]" and repeat each phone once per state.
void read_hts_context(LabelTier& t, const std::string& source, std::vector<std::string>& notes) {
  std::size_t full = 0;
  for (const Interval& v : t.intervals) {
    const auto caret = v.label.find('^'), minus = v.label.find('-'), plus = v.label.find('+');
    if (caret != std::string::npos && minus != std::string::npos && plus != std::string::npos && caret < minus &&
        minus < plus) {
      ++full;
    }
  }
  if (full == 0) return;
  if (full != t.intervals.size()) {
    refuse(source, "lab-hts-labels", std::to_string(full) + " of " + std::to_string(t.intervals.size()) +
                                         " labels are HTS full-context labels, the others not");
  }
  for (Interval& v : t.intervals) {
    if (v.label.ends_with(']')) {
      refuse(source, "lab-state-level",
             "HTS state-aligned labels (\"" + excerpt(v.label.substr(v.label.rfind('['))) +
                 "\" suffixes: one row per HMM state): give the phone-aligned file");
    }
    const auto minus = v.label.find('-'), plus = v.label.find('+');
    v.label = v.label.substr(minus + 1, plus - minus - 1);
  }
  notes.push_back("HTS full-context labels: the centre phone of each");
}

}  // namespace

std::vector<AlignedSegment> segments_of(const LabelTier& t, LabelSet set, const std::string& source) {
  std::vector<AlignedSegment> out;
  bool join_next = false;
  for (std::size_t i = 0; i < t.intervals.size(); ++i) {
    const Interval& v = t.intervals[i];
    const std::optional<MappedLabel> m = map_label(set, v.label);
    if (!m) {
      refuse(source, "alignment-unknown-label",
             "interval " + std::to_string(i + 1) + " (" + shortest_decimal(v.start_s) + " to " +
                 shortest_decimal(v.end_s) + " s) of tier \"" + t.name + "\": \"" + excerpt(v.label) +
                 "\" is not " + label_set_article(set) + " label (--phone-set names another set)");
    }
    if (m->kind != LabelKind::phone) {
      out.push_back({v.start_s, v.end_s, m->kind, Phone::SIL, v.start_s, v.label});
      join_next = false;
      continue;
    }
    if (join_next && !out.empty() && out.back().kind == LabelKind::phone && out.back().end_s == v.start_s &&
        out.back().phone == m->phones.front()) {
      out.back().end_s = v.end_s;  // a closure and its release: one phone from the closure on
      out.back().release_s = v.start_s;
      join_next = m->join == LabelJoin::with_next;
      continue;
    }
    if (m->join == LabelJoin::with_previous && !out.empty() && out.back().kind == LabelKind::phone &&
        out.back().end_s == v.start_s) {
      out.back().end_s = v.end_s;  // an aspiration: part of the stop before it
      join_next = false;
      continue;
    }
    const double step = (v.end_s - v.start_s) / static_cast<double>(m->phones.size());
    for (std::size_t k = 0; k < m->phones.size(); ++k) {
      const double a = v.start_s + step * static_cast<double>(k);
      const double b = k + 1 == m->phones.size() ? v.end_s : a + step;
      out.push_back({a, b, LabelKind::phone, m->phones[k], a, v.label});
    }
    join_next = m->join == LabelJoin::with_next;
  }
  return out;
}

std::string_view alignment_format_name(AlignmentFormat f) {
  switch (f) {
    case AlignmentFormat::textgrid: return "Praat TextGrid";
    case AlignmentFormat::htk_lab: return "HTK label file";
    case AlignmentFormat::seconds_lab: return "label file in seconds";
    case AlignmentFormat::esps: return "ESPS/xlabel label file";
    case AlignmentFormat::timit: return "TIMIT .phn/.wrd";
    case AlignmentFormat::mlf: return "HTK master label file";
    case AlignmentFormat::partitur: return "BAS Partitur";
    case AlignmentFormat::gentle: return "Gentle JSON";
  }
  return "?";
}

AlignmentFile read_alignment_file(std::string_view bytes, const std::string& path, const AlignmentFileOptions& o) {
  AlignmentFile out;
  const std::string ext = extension_of(path);
  AlignmentFormat found = sniff(bytes, path);
  // Rows of numbers are the weakest signature: a name that promises a format decides between
  // them (and that format's reader then says what is wrong with the rows).
  if (found == AlignmentFormat::htk_lab || found == AlignmentFormat::seconds_lab) {
    if (ext == ".phn" || ext == ".wrd") found = AlignmentFormat::timit;
    else if (ext == ".mlf") found = AlignmentFormat::mlf;
    else if (ext == ".par") found = AlignmentFormat::partitur;
    else if (ext == ".json") found = AlignmentFormat::gentle;
    else if (ext == ".textgrid") found = AlignmentFormat::textgrid;
  }
  if (o.format && *o.format != found && !(*o.format == AlignmentFormat::timit && found == AlignmentFormat::htk_lab)) {
    refuse(path, "alignment-format-mismatch", "the format given is " + std::string(alignment_format_name(*o.format)) +
                                                  ", the content is " + with_article(alignment_format_name(found)));
  }
  if (o.format) found = *o.format;
  if (extension_promises(ext) && !extension_agrees(found, ext)) {
    refuse(path, "alignment-format-mismatch",
           "the name ends in " + path.substr(path.size() - ext.size()) + " but the content is " + with_article(alignment_format_name(found)) +
               ": rename the file");
  }
  out.format = found;
  out.notes.push_back("format: " + std::string(alignment_format_name(found)));
  const std::string stem = o.utterance.value_or(stem_of(path));
  switch (found) {
    case AlignmentFormat::textgrid: out.alignment = read_textgrid(bytes, path); break;
    case AlignmentFormat::htk_lab:
    case AlignmentFormat::seconds_lab: {
      const LabFile lab = read_lab(bytes, path, found == AlignmentFormat::htk_lab ? LabTimeUnit::htk_100ns : LabTimeUnit::seconds);
      LabelTier t = to_tier(lab, "phones");
      if (found == AlignmentFormat::htk_lab) check_integer_units(t, found, path, o);
      read_hts_context(t, path, out.notes);
      out.alignment.end_s = t.end_s;
      out.alignment.tiers.push_back(std::move(t));
      break;
    }
    case AlignmentFormat::esps: {
      LabelTier t = read_esps_label(bytes, path, "phones");
      out.alignment.end_s = t.end_s;
      out.alignment.tiers.push_back(std::move(t));
      break;
    }
    case AlignmentFormat::timit: {
      if (!o.sample_rate) {
        refuse(path, "timit-needs-rate", "TIMIT offsets are samples: give the recording's sample rate");
      }
      if (ext == ".wrd") {
        refuse(path, "alignment-words-only", "a TIMIT .wrd holds words, not phones: give the .phn beside it");
      }
      LabelTier t = read_timit_label(bytes, path, *o.sample_rate, "phones");
      check_integer_units(t, found, path, o);
      out.alignment.end_s = t.end_s;
      out.alignment.tiers.push_back(std::move(t));
      break;
    }
    case AlignmentFormat::mlf: {
      std::vector<MlfEntry> entries = read_mlf(bytes, path);
      MlfEntry* pick = nullptr;
      for (MlfEntry& e : entries) {
        if (mlf_pattern_matches(e.pattern, stem)) {
          pick = &e;
          break;
        }
      }
      if (!pick && entries.size() == 1) pick = &entries[0];
      if (!pick) {
        refuse(path, "mlf-no-entry", "no entry names \"" + excerpt(stem) + "\" among its " + std::to_string(entries.size()) +
                                         " entries (the entry is the one whose pattern names the recording's file name)");
      }
      check_integer_units(pick->tier, AlignmentFormat::htk_lab, path, o);
      read_hts_context(pick->tier, path, out.notes);
      out.notes.push_back("MLF entry \"" + pick->pattern + "\" (line " + std::to_string(pick->line) + ")");
      pick->tier.name = "phones";
      out.alignment.end_s = pick->tier.end_s;
      out.alignment.tiers.push_back(std::move(pick->tier));
      break;
    }
    case AlignmentFormat::partitur: out.alignment = read_partitur(bytes, path); break;
    case AlignmentFormat::gentle: {
      GentleRead g = read_gentle(bytes, path);
      if (g.untimed_words > 0) {
        out.notes.push_back(std::to_string(g.untimed_words) + " word(s) Gentle did not find in the audio (no timing)");
      }
      out.alignment = std::move(g.alignment);
      break;
    }
  }
  const Choice c = choose_tier(out.alignment, path, o);
  out.tier = c.tier->name;
  out.notes.push_back("tier \"" + out.tier + "\" of " + std::to_string(out.alignment.tiers.size()) + " (" + c.why + ")");
  if (o.label_set) {
    out.label_set = *o.label_set;
  } else if (found == AlignmentFormat::timit) {
    out.label_set = LabelSet::timit;
  } else if (found == AlignmentFormat::gentle) {
    out.label_set = LabelSet::arpabet;
  } else {
    out.label_set = best_set(*c.tier).first;
  }
  out.segments = segments_of(*c.tier, out.label_set, path);
  std::size_t phones = 0, noises = 0, breaths = 0;
  double speech = 0;
  for (const AlignedSegment& s : out.segments) {
    if (s.kind == LabelKind::silence) continue;
    (s.kind == LabelKind::phone ? phones : s.kind == LabelKind::breath ? breaths : noises) += 1;
    speech += s.end_s - s.start_s;
  }
  out.notes.push_back("labels: " + std::string(label_set_name(out.label_set)) + " (" + std::to_string(phones) + " phones)");
  if (noises > 0) out.notes.push_back(std::to_string(noises) + " noise segment(s) (spn, oov ...) animated as rest");
  if (breaths > 0) out.notes.push_back(std::to_string(breaths) + " breath segment(s) animated as an inhalation (the mouth open until the next phone)");
  if (phones == 0) {
    refuse(path, "alignment-no-phones", "tier \"" + out.tier + "\" has no phone, only " +
                                            (out.segments.empty() ? std::string("nothing") : "silence or empty labels"));
  }
  const double span = o.audio_seconds ? *o.audio_seconds : out.alignment.end_s - out.alignment.start_s;
  if (span > 0 && speech / span < kMinSpeechCoverage) {
    refuse(path, "alignment-low-coverage",
           "the phones of tier \"" + out.tier + "\" cover " + seconds(speech) + " = " + percent(speech / span) + " of " +
               (o.audio_seconds ? "the recording" : "the file's span") + " (" + seconds(span) + "); at least " +
               percent(kMinSpeechCoverage) + " is speech in any recording an alignment belongs to");
  }
  return out;
}

}  // namespace fapcast
