#include "fapcast/rig/talkinghead_json.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>


namespace fapcast {

std::string talkinghead_json(std::span<const TimedText> words, std::span<const OculusViseme> visemes,
                             std::span<const std::string> names, const Eigen::MatrixXf& weights, FrameRate rate) {
  if (!rate.valid()) throw std::invalid_argument("talkinghead_json: invalid rate");
  const double num = rate.numerator, den = rate.denominator;
  if (weights.cols() != static_cast<Eigen::Index>(names.size()) || static_cast<std::size_t>(weights.rows()) != visemes.size())
    throw std::invalid_argument("talkinghead_json: want frames x names weights and one viseme per frame");
  const auto ms = [&](std::int64_t frame) { return 1000.0 * static_cast<double>(frame) * den / num; };
  // Arrays are filled first and moved in: ordered_json keeps its members in a vector, so a
  // reference to one member does not survive adding the next.
  nlohmann::json w = nlohmann::json::array(), wt = nlohmann::json::array(), wd = nlohmann::json::array();
  for (const TimedText& t : words) { w.push_back(t.text); wt.push_back(t.start_ms); wd.push_back(t.duration_ms); }
  nlohmann::json v = nlohmann::json::array(), vt = nlohmann::json::array(), vd = nlohmann::json::array();
  // TalkingHead's own names: ih oh ou are I O U (its morph targets viseme_I ...)
  static constexpr std::array<const char*, kOculusVisemeCount> kNames{"sil", "PP", "FF", "TH", "DD", "kk", "CH", "SS",
                                                                      "nn",  "RR", "aa", "E",  "I",  "O",  "U"};
  const auto frames = static_cast<std::int64_t>(visemes.size());
  for (std::int64_t f = 0; f < frames;) {
    std::int64_t e = f + 1;
    while (e < frames && visemes[static_cast<std::size_t>(e)] == visemes[static_cast<std::size_t>(f)]) ++e;
    v.push_back(kNames[static_cast<std::size_t>(visemes[static_cast<std::size_t>(f)])]);
    vt.push_back(ms(f));
    vd.push_back(ms(e) - ms(f));
    f = e;
  }
  nlohmann::json dt = nlohmann::json::array();
  for (std::int64_t f = 0; f < frames; ++f) dt.push_back(ms(f + 1) - ms(f));
  nlohmann::ordered_json vs = nlohmann::ordered_json::object();
  for (std::size_t c = 0; c < names.size(); ++c) {
    const auto col = weights.col(static_cast<Eigen::Index>(c));
    if (frames == 0 || col.maxCoeff() <= 0.0f) continue;
    nlohmann::json values = nlohmann::json::array();
    for (std::int64_t f = 0; f < frames; ++f) values.push_back(col[f]);
    vs[names[c]] = std::move(values);
  }
  nlohmann::ordered_json anim;
  anim["name"] = "fapcast";
  anim["dt"] = std::move(dt);
  anim["vs"] = std::move(vs);
  nlohmann::ordered_json j;
  j["generator"] = "fapcast";
  j["fps"] = rate.fps();
  j["words"] = std::move(w);
  j["wtimes"] = std::move(wt);
  j["wdurations"] = std::move(wd);
  j["visemes"] = std::move(v);
  j["vtimes"] = std::move(vt);
  j["vdurations"] = std::move(vd);
  j["anim"] = std::move(anim);
  return j.dump() + "\n";
}

}  // namespace fapcast
