#include "fapcast/talker/articulation.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/tsv_table.hpp"

namespace fapcast {
namespace {

constexpr std::array<std::string_view, kChannelCount> kChannelNames{
    "jaw", "lip_opening", "rounding", "spreading", "closure", "labiodental", "tongue_tip",
    "tongue_body"};

// spec/articulation.tsv, row for row (the test checks it). Generated from the phone classes
// described in spec/talker.md; edit both together.
constexpr std::array<PhoneChannelTarget, kPhoneCount * kChannelCount> kArticulation{{
    {"sil", Channel::jaw, 0.07f, {0.5f, 12.0f, 20.0f, 1.0f}},
    {"sil", Channel::lip_opening, 0.0f, {0.5f, 20.0f, 20.0f, 1.0f}},
    {"sil", Channel::rounding, 0.0f, {0.5f, 20.0f, 20.0f, 1.0f}},
    {"sil", Channel::spreading, 0.0f, {0.5f, 20.0f, 20.0f, 1.0f}},
    {"sil", Channel::closure, 0.0f, {0.5f, 20.0f, 20.0f, 1.0f}},
    {"sil", Channel::labiodental, 0.0f, {0.5f, 20.0f, 20.0f, 1.0f}},
    {"sil", Channel::tongue_tip, 0.1f, {0.5f, 20.0f, 20.0f, 1.0f}},
    {"sil", Channel::tongue_body, 0.2f, {0.5f, 20.0f, 20.0f, 1.0f}},
    {"AA", Channel::jaw, 0.41f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"AA", Channel::lip_opening, 0.96f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AA", Channel::rounding, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AA", Channel::spreading, 0.1f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AA", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AA", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AA", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"AA", Channel::tongue_body, 0.1f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"AE", Channel::jaw, 0.326f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"AE", Channel::lip_opening, 0.96f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AE", Channel::rounding, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AE", Channel::spreading, 0.4f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AE", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AE", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AE", Channel::tongue_tip, 0.2f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"AE", Channel::tongue_body, 0.2f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"AH", Channel::jaw, 0.27f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"AH", Channel::lip_opening, 0.96f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AH", Channel::rounding, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AH", Channel::spreading, 0.1f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AH", Channel::tongue_tip, 0.15f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"AH", Channel::tongue_body, 0.3f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"AO", Channel::jaw, 0.326f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"AO", Channel::lip_opening, 1.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AO", Channel::rounding, 0.5f, {1.0f, 12.0f, 14.0f, 1.0f}},
    {"AO", Channel::spreading, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AO", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AO", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AO", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"AO", Channel::tongue_body, 0.2f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"AW", Channel::jaw, 0.326f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"AW", Channel::lip_opening, 1.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AW", Channel::rounding, 0.3f, {1.0f, 12.0f, 14.0f, 1.0f}},
    {"AW", Channel::spreading, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AW", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AW", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AW", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"AW", Channel::tongue_body, 0.2f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"AX", Channel::jaw, 0.214f, {0.5f, 8.4f, 14.0f, 1.0f}},
    {"AX", Channel::lip_opening, 0.48f, {0.5f, 14.0f, 14.0f, 1.0f}},
    {"AX", Channel::rounding, 0.0f, {0.5f, 14.0f, 14.0f, 1.0f}},
    {"AX", Channel::spreading, 0.0f, {0.5f, 14.0f, 14.0f, 1.0f}},
    {"AX", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AX", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AX", Channel::tongue_tip, 0.15f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"AX", Channel::tongue_body, 0.3f, {0.5f, 20.0f, 20.0f, 1.0f}},
    {"AY", Channel::jaw, 0.326f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"AY", Channel::lip_opening, 0.96f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AY", Channel::rounding, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AY", Channel::spreading, 0.3f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"AY", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AY", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"AY", Channel::tongue_tip, 0.15f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"AY", Channel::tongue_body, 0.3f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"B", Channel::jaw, 0.046f, {5.0f, 15.0f, 25.0f, 1.0f}},
    {"B", Channel::lip_opening, 0.0f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"B", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"B", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"B", Channel::closure, 1.0f, {100.0f, 80.0f, 80.0f, 1.0f}},
    {"B", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"B", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"B", Channel::tongue_body, 0.3f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"CH", Channel::jaw, 0.074f, {2.0f, 12.0f, 20.0f, 1.0f}},
    {"CH", Channel::lip_opening, 0.48f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"CH", Channel::rounding, 0.45f, {0.8f, 14.0f, 14.0f, 1.0f}},
    {"CH", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"CH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"CH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"CH", Channel::tongue_tip, 0.8f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"CH", Channel::tongue_body, 0.6f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"D", Channel::jaw, 0.102f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"D", Channel::lip_opening, 0.48f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"D", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"D", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"D", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"D", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"D", Channel::tongue_tip, 1.0f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"D", Channel::tongue_body, 0.4f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"DH", Channel::jaw, 0.102f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"DH", Channel::lip_opening, 0.6f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"DH", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"DH", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"DH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"DH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"DH", Channel::tongue_tip, 1.0f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"DH", Channel::tongue_body, 0.3f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"EH", Channel::jaw, 0.242f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"EH", Channel::lip_opening, 0.96f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"EH", Channel::rounding, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"EH", Channel::spreading, 0.35f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"EH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"EH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"EH", Channel::tongue_tip, 0.2f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"EH", Channel::tongue_body, 0.4f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"ER", Channel::jaw, 0.158f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"ER", Channel::lip_opening, 0.6f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"ER", Channel::rounding, 0.35f, {1.0f, 12.0f, 14.0f, 1.0f}},
    {"ER", Channel::spreading, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"ER", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"ER", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"ER", Channel::tongue_tip, 0.5f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"ER", Channel::tongue_body, 0.5f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"EY", Channel::jaw, 0.186f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"EY", Channel::lip_opening, 0.96f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"EY", Channel::rounding, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"EY", Channel::spreading, 0.5f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"EY", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"EY", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"EY", Channel::tongue_tip, 0.2f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"EY", Channel::tongue_body, 0.6f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"F", Channel::jaw, 0.074f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"F", Channel::lip_opening, 0.1f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"F", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"F", Channel::spreading, 0.1f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"F", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"F", Channel::labiodental, 1.0f, {100.0f, 80.0f, 80.0f, 1.0f}},
    {"F", Channel::tongue_tip, 0.2f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"F", Channel::tongue_body, 0.3f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"G", Channel::jaw, 0.13f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"G", Channel::lip_opening, 0.6f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"G", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"G", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"G", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"G", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"G", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"G", Channel::tongue_body, 1.0f, {3.0f, 20.0f, 20.0f, 1.0f}},
    {"HH", Channel::jaw, 0.214f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"HH", Channel::lip_opening, 0.84f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"HH", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"HH", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"HH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"HH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"HH", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"HH", Channel::tongue_body, 0.3f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"IH", Channel::jaw, 0.158f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"IH", Channel::lip_opening, 0.96f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"IH", Channel::rounding, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"IH", Channel::spreading, 0.45f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"IH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"IH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"IH", Channel::tongue_tip, 0.2f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"IH", Channel::tongue_body, 0.7f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"IY", Channel::jaw, 0.102f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"IY", Channel::lip_opening, 0.96f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"IY", Channel::rounding, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"IY", Channel::spreading, 0.7f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"IY", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"IY", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"IY", Channel::tongue_tip, 0.25f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"IY", Channel::tongue_body, 0.9f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"JH", Channel::jaw, 0.074f, {2.0f, 12.0f, 20.0f, 1.0f}},
    {"JH", Channel::lip_opening, 0.48f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"JH", Channel::rounding, 0.45f, {0.8f, 14.0f, 14.0f, 1.0f}},
    {"JH", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"JH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"JH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"JH", Channel::tongue_tip, 0.8f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"JH", Channel::tongue_body, 0.6f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"K", Channel::jaw, 0.13f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"K", Channel::lip_opening, 0.6f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"K", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"K", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"K", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"K", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"K", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"K", Channel::tongue_body, 1.0f, {3.0f, 20.0f, 20.0f, 1.0f}},
    {"L", Channel::jaw, 0.13f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"L", Channel::lip_opening, 0.6f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"L", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"L", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"L", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"L", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"L", Channel::tongue_tip, 0.9f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"L", Channel::tongue_body, 0.3f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"M", Channel::jaw, 0.046f, {5.0f, 15.0f, 25.0f, 1.0f}},
    {"M", Channel::lip_opening, 0.0f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"M", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"M", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"M", Channel::closure, 1.0f, {100.0f, 80.0f, 80.0f, 1.0f}},
    {"M", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"M", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"M", Channel::tongue_body, 0.3f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"N", Channel::jaw, 0.102f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"N", Channel::lip_opening, 0.48f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"N", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"N", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"N", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"N", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"N", Channel::tongue_tip, 1.0f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"N", Channel::tongue_body, 0.4f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"NG", Channel::jaw, 0.13f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"NG", Channel::lip_opening, 0.6f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"NG", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"NG", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"NG", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"NG", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"NG", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"NG", Channel::tongue_body, 1.0f, {3.0f, 20.0f, 20.0f, 1.0f}},
    {"OW", Channel::jaw, 0.242f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"OW", Channel::lip_opening, 0.84f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"OW", Channel::rounding, 0.7f, {1.5f, 8.0f, 12.0f, 1.0f}},
    {"OW", Channel::spreading, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"OW", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"OW", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"OW", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"OW", Channel::tongue_body, 0.5f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"OY", Channel::jaw, 0.27f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"OY", Channel::lip_opening, 0.96f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"OY", Channel::rounding, 0.55f, {1.2f, 10.0f, 14.0f, 1.0f}},
    {"OY", Channel::spreading, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"OY", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"OY", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"OY", Channel::tongue_tip, 0.15f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"OY", Channel::tongue_body, 0.4f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"P", Channel::jaw, 0.046f, {5.0f, 15.0f, 25.0f, 1.0f}},
    {"P", Channel::lip_opening, 0.0f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"P", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"P", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"P", Channel::closure, 1.0f, {100.0f, 80.0f, 80.0f, 1.0f}},
    {"P", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"P", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"P", Channel::tongue_body, 0.3f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"R", Channel::jaw, 0.102f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"R", Channel::lip_opening, 0.4f, {3.0f, 20.0f, 20.0f, 1.0f}},
    {"R", Channel::rounding, 0.4f, {0.8f, 14.0f, 14.0f, 1.0f}},
    {"R", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"R", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"R", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"R", Channel::tongue_tip, 0.6f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"R", Channel::tongue_body, 0.5f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"S", Channel::jaw, 0.025f, {2.0f, 12.0f, 20.0f, 1.0f}},
    {"S", Channel::lip_opening, 0.36f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"S", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"S", Channel::spreading, 0.3f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"S", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"S", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"S", Channel::tongue_tip, 0.9f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"S", Channel::tongue_body, 0.5f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"SH", Channel::jaw, 0.074f, {2.0f, 12.0f, 20.0f, 1.0f}},
    {"SH", Channel::lip_opening, 0.48f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"SH", Channel::rounding, 0.45f, {0.8f, 14.0f, 14.0f, 1.0f}},
    {"SH", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"SH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"SH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"SH", Channel::tongue_tip, 0.7f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"SH", Channel::tongue_body, 0.6f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"T", Channel::jaw, 0.102f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"T", Channel::lip_opening, 0.48f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"T", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"T", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"T", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"T", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"T", Channel::tongue_tip, 1.0f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"T", Channel::tongue_body, 0.4f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"TH", Channel::jaw, 0.102f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"TH", Channel::lip_opening, 0.6f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"TH", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"TH", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"TH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"TH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"TH", Channel::tongue_tip, 1.0f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"TH", Channel::tongue_body, 0.3f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"UH", Channel::jaw, 0.158f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"UH", Channel::lip_opening, 0.6f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"UH", Channel::rounding, 0.55f, {1.2f, 10.0f, 14.0f, 1.0f}},
    {"UH", Channel::spreading, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"UH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"UH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"UH", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"UH", Channel::tongue_body, 0.65f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"UW", Channel::jaw, 0.102f, {1.0f, 8.4f, 14.0f, 1.0f}},
    {"UW", Channel::lip_opening, 0.36f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"UW", Channel::rounding, 0.95f, {2.0f, 6.0f, 12.0f, 1.0f}},
    {"UW", Channel::spreading, 0.0f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"UW", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"UW", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"UW", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"UW", Channel::tongue_body, 0.85f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"V", Channel::jaw, 0.074f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"V", Channel::lip_opening, 0.1f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"V", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"V", Channel::spreading, 0.1f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"V", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"V", Channel::labiodental, 1.0f, {100.0f, 80.0f, 80.0f, 1.0f}},
    {"V", Channel::tongue_tip, 0.2f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"V", Channel::tongue_body, 0.3f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"W", Channel::jaw, 0.074f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"W", Channel::lip_opening, 0.1f, {3.0f, 10.0f, 15.0f, 1.0f}},
    {"W", Channel::rounding, 0.9f, {3.0f, 10.0f, 15.0f, 1.0f}},
    {"W", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"W", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"W", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"W", Channel::tongue_tip, 0.1f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"W", Channel::tongue_body, 0.7f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"Y", Channel::jaw, 0.074f, {0.6f, 10.8f, 18.0f, 1.0f}},
    {"Y", Channel::lip_opening, 0.48f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"Y", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"Y", Channel::spreading, 0.4f, {1.0f, 14.0f, 14.0f, 1.0f}},
    {"Y", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"Y", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"Y", Channel::tongue_tip, 0.2f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"Y", Channel::tongue_body, 0.9f, {1.0f, 20.0f, 20.0f, 1.0f}},
    {"Z", Channel::jaw, 0.025f, {2.0f, 12.0f, 20.0f, 1.0f}},
    {"Z", Channel::lip_opening, 0.36f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"Z", Channel::rounding, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"Z", Channel::spreading, 0.3f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"Z", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"Z", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"Z", Channel::tongue_tip, 0.9f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"Z", Channel::tongue_body, 0.5f, {0.3f, 20.0f, 20.0f, 1.0f}},
    {"ZH", Channel::jaw, 0.074f, {2.0f, 12.0f, 20.0f, 1.0f}},
    {"ZH", Channel::lip_opening, 0.48f, {0.4f, 20.0f, 20.0f, 1.0f}},
    {"ZH", Channel::rounding, 0.45f, {0.8f, 14.0f, 14.0f, 1.0f}},
    {"ZH", Channel::spreading, 0.0f, {0.1f, 25.0f, 25.0f, 1.0f}},
    {"ZH", Channel::closure, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"ZH", Channel::labiodental, 0.0f, {1.0f, 15.0f, 15.0f, 1.0f}},
    {"ZH", Channel::tongue_tip, 0.7f, {5.0f, 30.0f, 30.0f, 1.0f}},
    {"ZH", Channel::tongue_body, 0.6f, {0.3f, 20.0f, 20.0f, 1.0f}},
}};

// spec/articulation_shapes.tsv, row for row.
constexpr std::array<ChannelShapeRow, 20> kChannelShapes{{
    {Channel::jaw, "jawOpen", 1.0f, std::nullopt, false},
    {Channel::lip_opening, "mouthLowerDown_L", 1.0f, std::nullopt, true},
    {Channel::lip_opening, "mouthLowerDown_R", 1.0f, std::nullopt, true},
    {Channel::lip_opening, "mouthUpperUp_L", 0.7f, std::nullopt, true},
    {Channel::lip_opening, "mouthUpperUp_R", 0.7f, std::nullopt, true},
    {Channel::rounding, "mouthPucker", 0.6f, std::nullopt, false},
    {Channel::rounding, "mouthFunnel", 0.1f, std::nullopt, true},
    {Channel::rounding, "mouthPress_L", 0.3f, std::nullopt, true},
    {Channel::rounding, "mouthPress_R", 0.3f, std::nullopt, true},
    {Channel::spreading, "mouthStretch_L", 0.4f, std::nullopt, false},
    {Channel::spreading, "mouthStretch_R", 0.4f, std::nullopt, false},
    {Channel::spreading, "mouthSmile_L", 0.3f, std::nullopt, false},
    {Channel::spreading, "mouthSmile_R", 0.3f, std::nullopt, false},
    {Channel::closure, "mouthClose", 0.83f, Channel::jaw, false},
    {Channel::closure, "mouthPress_L", 0.3f, std::nullopt, false},
    {Channel::closure, "mouthPress_R", 0.3f, std::nullopt, false},
    {Channel::labiodental, "mouthRollLower", 0.35f, std::nullopt, false},
    {Channel::labiodental, "mouthClose", 0.25f, Channel::jaw, false},
    {Channel::labiodental, "mouthUpperUp_L", 0.15f, std::nullopt, false},
    {Channel::labiodental, "mouthUpperUp_R", 0.15f, std::nullopt, false},
}};

constexpr std::size_t kArticulationPhones = kArticulation.size() / kChannelCount;

// Phone-indexed view of kArticulation, built once.
const std::array<PhoneArticulation, kArticulationPhones>& by_phone() {
  static const auto table = [] {
    std::array<PhoneArticulation, kArticulationPhones> t{};
    for (std::size_t i = 0; i < kArticulation.size(); ++i) {
      const auto& row = kArticulation[i];
      t[i / kChannelCount].target[static_cast<std::size_t>(row.channel)] = row.target;
      t[i / kChannelCount].dominance[static_cast<std::size_t>(row.channel)] = row.dominance;
    }
    return t;
  }();
  return table;
}

}  // namespace

std::string_view channel_name(Channel channel) {
  return kChannelNames.at(static_cast<std::size_t>(channel));
}

Channel channel_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kChannelNames.size(); ++i)
    if (kChannelNames[i] == name) return static_cast<Channel>(i);
  throw std::invalid_argument("unknown articulatory channel '" + std::string(name) + "'");
}

std::span<const PhoneChannelTarget> articulation_table() { return kArticulation; }

std::vector<std::string_view> articulation_phones() {
  std::vector<std::string_view> phones;
  for (std::size_t i = 0; i < kArticulation.size(); i += kChannelCount)
    phones.push_back(kArticulation[i].phone);
  return phones;
}

const PhoneArticulation& phone_articulation(std::string_view phone) {
  std::string_view key = phone;
  if (!key.empty() && std::isdigit(static_cast<unsigned char>(key.back())) != 0)
    key.remove_suffix(1);
  if (key.empty() || key == "sp" || key == "pau" || key == "SIL") key = "sil";
  for (std::size_t p = 0; p < kArticulationPhones; ++p)
    if (kArticulation[p * kChannelCount].phone == key) return by_phone()[p];
  throw std::invalid_argument("unknown phone '" + std::string(phone) +
                              "' (the articulation table knows the 39 ARPAbet phones and sil)");
}

const PhoneArticulation& phone_articulation(Phone phone) {
  return phone_articulation(phone == Phone::SIL ? std::string_view("sil") : arpabet(phone));
}

std::span<const ChannelShapeRow> channel_shape_table() { return kChannelShapes; }

ShapeMapper::ShapeMapper(const FaceModel& face) : shape_count_(face.expressions.size()) {
  for (const auto& row : kChannelShapes) shape_of_row_.push_back(face.expression_index(row.shape));
}

std::vector<float> ShapeMapper::operator()(const std::array<float, kChannelCount>& channels) const {
  std::vector<float> weights(shape_count_, 0.0f);
  const auto value = [&](Channel c) { return channels[static_cast<std::size_t>(c)]; };
  const float gate = (1.0f - value(Channel::closure)) * (1.0f - value(Channel::labiodental));
  for (std::size_t r = 0; r < kChannelShapes.size(); ++r) {
    const auto& row = kChannelShapes[r];
    float w = value(row.channel) * row.weight;
    if (row.scale_by) w *= value(*row.scale_by);
    if (row.gated) w *= gate;
    weights[shape_of_row_[r]] += w;
  }
  for (float& w : weights) w = std::clamp(w, 0.0f, 1.0f);
  return weights;
}

double jaw_opening_angle_rad(float jaw) { return 0.35 * static_cast<double>(jaw); }

std::vector<ArticulationSpecRow> read_articulation_spec(const std::filesystem::path& file) {
  std::vector<ArticulationSpecRow> out;
  for (const auto& row : read_tsv(file, 7))
    out.push_back({row.fields[0], row.fields[1], tsv_float(file, row, 2), tsv_float(file, row, 3),
                   tsv_float(file, row, 4), tsv_float(file, row, 5), tsv_float(file, row, 6)});
  return out;
}

std::vector<ChannelShapeSpecRow> read_channel_shape_spec(const std::filesystem::path& file) {
  std::vector<ChannelShapeSpecRow> out;
  for (const auto& row : read_tsv(file, 5))
    out.push_back({row.fields[0], row.fields[1], tsv_float(file, row, 2), row.fields[3],
                   tsv_integer(file, row, 4, 0, 1) == 1});
  return out;
}

}  // namespace fapcast
