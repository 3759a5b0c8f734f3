#include "fapcast/codec/fap_table.hpp"

#include <cassert>

namespace fapcast {
namespace {

// One row per FAP: number, name, FAPU, unidirectional, direction of positive values, group,
// feature point, second feature point, QP, default I range, default P range.
// Left and right are the face's own sides. Unverified against the standard: the unidirectional
// flags, head-rotation directions and the eyeball FAPs' feature points (spec/faps.tsv).
constexpr std::array<FapInfo, kFapCount> kFaps{{
    {1, "viseme", Fapu::kNone, false, "-", 1, std::nullopt, std::nullopt, 0, 0, 0},  // viseme: select1, select2, blend, def
    {2, "expression", Fapu::kNone, false, "-", 1, std::nullopt, std::nullopt, 0, 0, 0},  // expression: select1, intensity1, select2, intensity2, init_face, def
    {3, "open_jaw", Fapu::kMNS, true, "down", 2, FeaturePoint{2, 1}, std::nullopt, 4, 1080, 360},
    {4, "lower_t_midlip", Fapu::kMNS, false, "down", 2, FeaturePoint{2, 2}, std::nullopt, 2, 600, 180},
    {5, "raise_b_midlip", Fapu::kMNS, false, "up", 2, FeaturePoint{2, 3}, std::nullopt, 2, 1860, 600},
    {6, "stretch_l_cornerlip", Fapu::kMW, false, "left", 2, FeaturePoint{2, 4}, std::nullopt, 2, 600, 180},
    {7, "stretch_r_cornerlip", Fapu::kMW, false, "right", 2, FeaturePoint{2, 5}, std::nullopt, 2, 600, 180},
    {8, "lower_t_lip_lm", Fapu::kMNS, false, "down", 2, FeaturePoint{2, 6}, std::nullopt, 2, 600, 180},
    {9, "lower_t_lip_rm", Fapu::kMNS, false, "down", 2, FeaturePoint{2, 7}, std::nullopt, 2, 600, 180},
    {10, "raise_b_lip_lm", Fapu::kMNS, false, "up", 2, FeaturePoint{2, 8}, std::nullopt, 2, 1860, 600},
    {11, "raise_b_lip_rm", Fapu::kMNS, false, "up", 2, FeaturePoint{2, 9}, std::nullopt, 2, 1860, 600},
    {12, "raise_l_cornerlip", Fapu::kMNS, false, "up", 2, FeaturePoint{2, 4}, std::nullopt, 2, 600, 180},
    {13, "raise_r_cornerlip", Fapu::kMNS, false, "up", 2, FeaturePoint{2, 5}, std::nullopt, 2, 600, 180},
    {14, "thrust_jaw", Fapu::kMNS, true, "forward", 2, FeaturePoint{2, 1}, std::nullopt, 1, 600, 180},
    {15, "shift_jaw", Fapu::kMW, false, "right", 2, FeaturePoint{2, 1}, std::nullopt, 1, 1080, 360},
    {16, "push_b_lip", Fapu::kMNS, false, "forward", 2, FeaturePoint{2, 3}, std::nullopt, 1, 1080, 360},
    {17, "push_t_lip", Fapu::kMNS, false, "forward", 2, FeaturePoint{2, 2}, std::nullopt, 1, 1080, 360},
    {18, "depress_chin", Fapu::kMNS, false, "up", 2, FeaturePoint{2, 10}, std::nullopt, 1, 420, 180},
    {19, "close_t_l_eyelid", Fapu::kIRISD, false, "down", 3, FeaturePoint{3, 1}, std::nullopt, 1, 1080, 600},
    {20, "close_t_r_eyelid", Fapu::kIRISD, false, "down", 3, FeaturePoint{3, 2}, std::nullopt, 1, 1080, 600},
    {21, "close_b_l_eyelid", Fapu::kIRISD, false, "up", 3, FeaturePoint{3, 3}, std::nullopt, 1, 600, 240},
    {22, "close_b_r_eyelid", Fapu::kIRISD, false, "up", 3, FeaturePoint{3, 4}, std::nullopt, 1, 600, 240},
    {23, "yaw_l_eyeball", Fapu::kAU, false, "left", 3, std::nullopt, std::nullopt, 128, 1200, 420},
    {24, "yaw_r_eyeball", Fapu::kAU, false, "left", 3, std::nullopt, std::nullopt, 128, 1200, 420},
    {25, "pitch_l_eyeball", Fapu::kAU, false, "down", 3, std::nullopt, std::nullopt, 128, 900, 300},
    {26, "pitch_r_eyeball", Fapu::kAU, false, "down", 3, std::nullopt, std::nullopt, 128, 900, 300},
    {27, "thrust_l_eyeball", Fapu::kES, false, "forward", 3, std::nullopt, std::nullopt, 1, 600, 180},
    {28, "thrust_r_eyeball", Fapu::kES, false, "forward", 3, std::nullopt, std::nullopt, 1, 600, 180},
    {29, "dilate_l_pupil", Fapu::kIRISD, false, "growing", 3, FeaturePoint{3, 5}, std::nullopt, 1, 420, 120},
    {30, "dilate_r_pupil", Fapu::kIRISD, false, "growing", 3, FeaturePoint{3, 6}, std::nullopt, 1, 420, 120},
    {31, "raise_l_i_eyebrow", Fapu::kENS, false, "up", 4, FeaturePoint{4, 1}, std::nullopt, 2, 900, 360},
    {32, "raise_r_i_eyebrow", Fapu::kENS, false, "up", 4, FeaturePoint{4, 2}, std::nullopt, 2, 900, 360},
    {33, "raise_l_m_eyebrow", Fapu::kENS, false, "up", 4, FeaturePoint{4, 3}, std::nullopt, 2, 900, 360},
    {34, "raise_r_m_eyebrow", Fapu::kENS, false, "up", 4, FeaturePoint{4, 4}, std::nullopt, 2, 900, 360},
    {35, "raise_l_o_eyebrow", Fapu::kENS, false, "up", 4, FeaturePoint{4, 5}, std::nullopt, 2, 900, 360},
    {36, "raise_r_o_eyebrow", Fapu::kENS, false, "up", 4, FeaturePoint{4, 6}, std::nullopt, 2, 900, 360},
    {37, "squeeze_l_eyebrow", Fapu::kES, false, "right", 4, FeaturePoint{4, 1}, std::nullopt, 1, 900, 300},
    {38, "squeeze_r_eyebrow", Fapu::kES, false, "left", 4, FeaturePoint{4, 2}, std::nullopt, 1, 900, 300},
    {39, "puff_l_cheek", Fapu::kES, false, "left", 5, FeaturePoint{5, 1}, std::nullopt, 2, 900, 300},
    {40, "puff_r_cheek", Fapu::kES, false, "right", 5, FeaturePoint{5, 2}, std::nullopt, 2, 900, 300},
    {41, "lift_l_cheek", Fapu::kENS, true, "up", 5, FeaturePoint{5, 3}, std::nullopt, 2, 600, 180},
    {42, "lift_r_cheek", Fapu::kENS, true, "up", 5, FeaturePoint{5, 4}, std::nullopt, 2, 600, 180},
    {43, "shift_tongue_tip", Fapu::kMW, false, "right", 6, FeaturePoint{6, 1}, std::nullopt, 1, 1080, 420},
    {44, "raise_tongue_tip", Fapu::kMNS, false, "up", 6, FeaturePoint{6, 1}, std::nullopt, 1, 1080, 420},
    {45, "thrust_tongue_tip", Fapu::kMW, false, "forward", 6, FeaturePoint{6, 1}, std::nullopt, 1, 1080, 420},
    {46, "raise_tongue", Fapu::kMNS, false, "up", 6, FeaturePoint{6, 2}, std::nullopt, 1, 1080, 420},
    {47, "tongue_roll", Fapu::kAU, true, "concave-up", 6, FeaturePoint{6, 3}, FeaturePoint{6, 4}, 512, 1080, 420},
    {48, "head_pitch", Fapu::kAU, false, "down", 7, std::nullopt, std::nullopt, 170, 1860, 600},
    {49, "head_yaw", Fapu::kAU, false, "left", 7, std::nullopt, std::nullopt, 170, 1860, 600},
    {50, "head_roll", Fapu::kAU, false, "right", 7, std::nullopt, std::nullopt, 170, 1860, 600},
    {51, "lower_t_midlip_o", Fapu::kMNS, false, "down", 8, FeaturePoint{8, 1}, std::nullopt, 2, 600, 180},
    {52, "raise_b_midlip_o", Fapu::kMNS, false, "up", 8, FeaturePoint{8, 2}, std::nullopt, 2, 1860, 600},
    {53, "stretch_l_cornerlip_o", Fapu::kMW, false, "left", 8, FeaturePoint{8, 3}, std::nullopt, 2, 600, 180},
    {54, "stretch_r_cornerlip_o", Fapu::kMW, false, "right", 8, FeaturePoint{8, 4}, std::nullopt, 2, 600, 180},
    {55, "lower_t_lip_lm_o", Fapu::kMNS, false, "down", 8, FeaturePoint{8, 5}, std::nullopt, 2, 600, 180},
    {56, "lower_t_lip_rm_o", Fapu::kMNS, false, "down", 8, FeaturePoint{8, 6}, std::nullopt, 2, 600, 180},
    {57, "raise_b_lip_lm_o", Fapu::kMNS, false, "up", 8, FeaturePoint{8, 7}, std::nullopt, 2, 1860, 600},
    {58, "raise_b_lip_rm_o", Fapu::kMNS, false, "up", 8, FeaturePoint{8, 8}, std::nullopt, 2, 1860, 600},
    {59, "raise_l_cornerlip_o", Fapu::kMNS, false, "up", 8, FeaturePoint{8, 3}, std::nullopt, 2, 600, 180},
    {60, "raise_r_cornerlip_o", Fapu::kMNS, false, "up", 8, FeaturePoint{8, 4}, std::nullopt, 2, 600, 180},
    {61, "stretch_l_nose", Fapu::kENS, false, "left", 9, FeaturePoint{9, 1}, std::nullopt, 1, 540, 120},
    {62, "stretch_r_nose", Fapu::kENS, false, "right", 9, FeaturePoint{9, 2}, std::nullopt, 1, 540, 120},
    {63, "raise_nose", Fapu::kENS, false, "up", 9, FeaturePoint{9, 3}, std::nullopt, 1, 680, 180},
    {64, "bend_nose", Fapu::kENS, false, "right", 9, FeaturePoint{9, 3}, std::nullopt, 1, 900, 180},
    {65, "raise_l_ear", Fapu::kENS, false, "up", 10, FeaturePoint{10, 1}, std::nullopt, 1, 900, 240},
    {66, "raise_r_ear", Fapu::kENS, false, "up", 10, FeaturePoint{10, 2}, std::nullopt, 1, 900, 240},
    {67, "pull_l_ear", Fapu::kENS, false, "left", 10, FeaturePoint{10, 3}, std::nullopt, 1, 900, 300},
    {68, "pull_r_ear", Fapu::kENS, false, "right", 10, FeaturePoint{10, 4}, std::nullopt, 1, 900, 300},
}};

constexpr bool rows_are_numbered_in_order() {
  for (int i = 0; i < kFapCount; ++i)
    if (kFaps[static_cast<std::size_t>(i)].number != i + 1) return false;
  return true;
}
static_assert(rows_are_numbered_in_order(), "row n-1 must hold FAP n");

constexpr std::array<FapRange, kGroupCount> kGroups{{
    {1, 2}, {3, 18}, {19, 30}, {31, 38}, {39, 42}, {43, 47}, {48, 50}, {51, 60}, {61, 64}, {65, 68},
}};

}  // namespace

std::span<const FapInfo, kFapCount> fap_table() { return kFaps; }

const FapInfo& fap_info(int number) {
  assert(number >= 1 && number <= kFapCount);
  return kFaps[static_cast<std::size_t>(number - 1)];
}

std::optional<int> fap_number(std::string_view name) {
  for (const auto& row : kFaps)
    if (row.name == name) return row.number;
  return std::nullopt;
}

FapRange fap_group(int group) {
  assert(group >= 1 && group <= kGroupCount);
  return kGroups[static_cast<std::size_t>(group - 1)];
}

}  // namespace fapcast
