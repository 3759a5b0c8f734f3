#pragma once
// Three small .fap readers that read a file the way each real player's own parser does, written
// from the facts in spec/fap-text.md ("Players"), not from their code: Xface's FAPFile, Greta's
// FAPParser, VREng's Bap::parse. A "crash" of the player is a PlayerCrash. Tests read fapcast's
// output back with them.
#include "fapcast/codec/fap_table.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fapcast::test {

struct PlayerCrash : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What a player holds for one frame: FAP n's tokens (FAP 1/2: the fields it reads), by FAP.
struct PlayerFrame {
  std::map<int, std::vector<double>> faps;
  bool operator==(const PlayerFrame&) const = default;
};

struct PlayerRead {
  double fps = 0;
  std::vector<PlayerFrame> frames;
};

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::string line;
  std::istringstream in(text);
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

inline std::vector<std::string> split_blanks(const std::string& s) {  // spaces and tabs, CR dropped
  std::vector<std::string> out;
  std::string t;
  for (const char c : s) {
    if (c == ' ' || c == '\t' || c == '\r') {
      if (!t.empty()) out.push_back(t), t.clear();
    } else {
      t += c;
    }
  }
  if (!t.empty()) out.push_back(t);
  return out;
}

// Xface: '#' lines only before the header; header version (float), name (one token), fps (cast to
// short), count; exactly 68 mask tokens, any non-zero set; the frame number is a 0-based row index
// with no bounds check; FAP 1 takes 4 tokens, FAP 2 takes 6; values by atof; rows the file does
// not give stay zero; CRLF is fine.
inline PlayerRead xface_read(const std::string& text) {
  const auto lines = lines_of(text);
  std::size_t i = 0;
  while (i < lines.size() && !lines[i].empty() && lines[i][0] == '#') ++i;
  if (i >= lines.size()) throw PlayerCrash("xface: no header");
  const auto h = split_blanks(lines[i++]);
  if (h.size() != 4) throw PlayerCrash("xface: the header is not version, one-token name, fps, count");
  PlayerRead r;
  r.fps = static_cast<short>(std::atof(h[2].c_str()));
  const long count = std::atol(h[3].c_str());
  r.frames.resize(static_cast<std::size_t>(std::max(count, 0L)));
  for (; i + 1 < lines.size(); i += 2) {
    const auto mask = split_blanks(lines[i]);
    if (mask.size() != 68) throw PlayerCrash("xface: a mask line of " + std::to_string(mask.size()) + " tokens");
    const auto values = split_blanks(lines[i + 1]);
    if (values.empty()) throw PlayerCrash("xface: an empty value line");
    const long row = std::atol(values[0].c_str());
    if (row < 0 || row >= count) throw PlayerCrash("xface: row " + std::to_string(row) + " past its frames");
    PlayerFrame f;
    std::size_t v = 1;
    for (int n = 1; n <= 68; ++n) {
      if (std::atof(mask[static_cast<std::size_t>(n - 1)].c_str()) == 0) continue;
      const std::size_t take = n == 1 ? 4 : n == 2 ? 6 : 1;
      for (std::size_t k = 0; k < take; ++k, ++v)
        f.faps[n].push_back(v < values.size() ? std::atof(values[v].c_str()) : 0.0);
    }
    r.frames[static_cast<std::size_t>(row)] = f;
  }
  return r;
}

// Greta: the header line ignored; lines read strictly in pairs (a comment is taken as a mask
// line); up to 69 mask tokens, with 69 the first is unused; only "1" is set; FAP 1 and FAP 2 one
// integer each; values by parseInt: the first token with a decimal point ends the file, silently;
// frame numbers kept as written.
inline PlayerRead greta_read(const std::string& text) {
  const auto lines = lines_of(text);
  PlayerRead r;
  for (std::size_t i = 1; i + 1 < lines.size(); i += 2) {
    auto mask = split_blanks(lines[i]);
    if (mask.size() > 69) throw PlayerCrash("greta: more than 69 mask tokens");
    if (mask.size() == 69) mask.erase(mask.begin());
    const auto values = split_blanks(lines[i + 1]);
    PlayerFrame f;
    std::size_t v = 1;
    for (std::size_t n = 1; n <= mask.size(); ++n) {
      if (mask[n - 1] != "1") continue;
      if (v >= values.size()) break;
      if (values[v].find('.') != std::string::npos) return r;  // parseInt stops here: the file ends
      f.faps[static_cast<int>(n)].push_back(static_cast<double>(std::atol(values[v++].c_str())));
    }
    r.frames.push_back(f);
  }
  return r;
}

// VREng: split on spaces only (a tab in the header crashes it; a stray CR is a token of its own);
// lines starting with '#' skipped; version by prefix "2.0"/"2.1", 2.0 values divided by 20; the
// 4th header token the count; 68 mask tokens read in order (an extra one shifts every value);
// FAP 1 and FAP 2 one token each; values by atof; frame numbers ignored, frames by order.
inline PlayerRead vreng_read(const std::string& text) {
  const auto split_spaces = [](const std::string& s) {
    std::vector<std::string> out;
    std::string t;
    for (const char c : s) {
      if (c == ' ') {
        if (!t.empty()) out.push_back(t), t.clear();
      } else {
        t += c;
      }
    }
    if (!t.empty()) out.push_back(t);
    return out;
  };
  std::vector<std::string> lines;
  for (const auto& l : lines_of(text))
    if (l.empty() || l[0] != '#') lines.push_back(l);
  if (lines.empty()) throw PlayerCrash("vreng: no header");
  if (lines[0].find('\t') != std::string::npos) throw PlayerCrash("vreng: a tab in the header");
  const auto h = split_spaces(lines[0]);
  if (h.size() < 4 || (h[0].rfind("2.0", 0) != 0 && h[0].rfind("2.1", 0) != 0)) throw PlayerCrash("vreng: header");
  const double scale = h[0].rfind("2.0", 0) == 0 ? 1.0 / 20 : 1.0;
  PlayerRead r;
  const long count = std::atol(h[3].c_str());
  for (std::size_t i = 1; i + 1 < lines.size() && static_cast<long>(r.frames.size()) < count; i += 2) {
    const auto mask = split_spaces(lines[i]);
    const auto values = split_spaces(lines[i + 1]);
    PlayerFrame f;
    std::size_t v = 1;
    for (int n = 1; n <= 68 && static_cast<std::size_t>(n) <= mask.size(); ++n) {
      if (std::atof(mask[static_cast<std::size_t>(n - 1)].c_str()) == 0) continue;
      f.faps[n].push_back(v < values.size() ? std::atof(values[v].c_str()) * scale : 0.0);
      ++v;
    }
    r.frames.push_back(f);
  }
  return r;
}

}  // namespace fapcast::test
