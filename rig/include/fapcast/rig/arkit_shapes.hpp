#pragma once
// Apple ARKit's 52 face blendshapes (ARFaceAnchor.BlendShapeLocation), in the order of ARKit's
// coefficient index, which is also the column order of Live Link Face's CSV and of Unreal's
// EARFaceBlendShape (spec/rigs.md, "ARKit"). Each row: the name as ARKit and glTF avatars spell it
// (camelCase), the ICT-FaceKit shapes it is made of on the ICT face, and the group the synthesis
// drives. ICT carries 53 shapes named after ARKit's: the same with _L/_R for Left/Right, cheekPuff
// and browInnerUp split in two halves (an ARKit weight moves both), and no tongue.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace fapcast {

enum class ArkitGroup : unsigned char {
  kEye,     // not moved by speech: weight 0
  kBrow,    // not moved by speech: weight 0
  kMouth,   // fitted: lips, jaw, cheeks, nose
  kTongue,  // tongueOut, from the tongue track
};

struct ArkitShape {
  std::string_view name;                  // "jawOpen"
  std::array<std::string_view, 2> ict;    // ICT shapes summed ("" when fewer)
  ArkitGroup group;
};

inline constexpr std::size_t kArkitShapeCount = 52;

// clang-format off
inline constexpr std::array<ArkitShape, kArkitShapeCount> kArkitShapes{{
    {"eyeBlinkLeft",        {"eyeBlink_L", ""},           ArkitGroup::kEye},
    {"eyeLookDownLeft",     {"eyeLookDown_L", ""},        ArkitGroup::kEye},
    {"eyeLookInLeft",       {"eyeLookIn_L", ""},          ArkitGroup::kEye},
    {"eyeLookOutLeft",      {"eyeLookOut_L", ""},         ArkitGroup::kEye},
    {"eyeLookUpLeft",       {"eyeLookUp_L", ""},          ArkitGroup::kEye},
    {"eyeSquintLeft",       {"eyeSquint_L", ""},          ArkitGroup::kEye},
    {"eyeWideLeft",         {"eyeWide_L", ""},            ArkitGroup::kEye},
    {"eyeBlinkRight",       {"eyeBlink_R", ""},           ArkitGroup::kEye},
    {"eyeLookDownRight",    {"eyeLookDown_R", ""},        ArkitGroup::kEye},
    {"eyeLookInRight",      {"eyeLookIn_R", ""},          ArkitGroup::kEye},
    {"eyeLookOutRight",     {"eyeLookOut_R", ""},         ArkitGroup::kEye},
    {"eyeLookUpRight",      {"eyeLookUp_R", ""},          ArkitGroup::kEye},
    {"eyeSquintRight",      {"eyeSquint_R", ""},          ArkitGroup::kEye},
    {"eyeWideRight",        {"eyeWide_R", ""},            ArkitGroup::kEye},
    {"jawForward",          {"jawForward", ""},           ArkitGroup::kMouth},
    {"jawRight",            {"jawRight", ""},             ArkitGroup::kMouth},
    {"jawLeft",             {"jawLeft", ""},              ArkitGroup::kMouth},
    {"jawOpen",             {"jawOpen", ""},              ArkitGroup::kMouth},
    {"mouthClose",          {"mouthClose", ""},           ArkitGroup::kMouth},
    {"mouthFunnel",         {"mouthFunnel", ""},          ArkitGroup::kMouth},
    {"mouthPucker",         {"mouthPucker", ""},          ArkitGroup::kMouth},
    {"mouthRight",          {"mouthRight", ""},           ArkitGroup::kMouth},
    {"mouthLeft",           {"mouthLeft", ""},            ArkitGroup::kMouth},
    {"mouthSmileLeft",      {"mouthSmile_L", ""},         ArkitGroup::kMouth},
    {"mouthSmileRight",     {"mouthSmile_R", ""},         ArkitGroup::kMouth},
    {"mouthFrownLeft",      {"mouthFrown_L", ""},         ArkitGroup::kMouth},
    {"mouthFrownRight",     {"mouthFrown_R", ""},         ArkitGroup::kMouth},
    {"mouthDimpleLeft",     {"mouthDimple_L", ""},        ArkitGroup::kMouth},
    {"mouthDimpleRight",    {"mouthDimple_R", ""},        ArkitGroup::kMouth},
    {"mouthStretchLeft",    {"mouthStretch_L", ""},       ArkitGroup::kMouth},
    {"mouthStretchRight",   {"mouthStretch_R", ""},       ArkitGroup::kMouth},
    {"mouthRollLower",      {"mouthRollLower", ""},       ArkitGroup::kMouth},
    {"mouthRollUpper",      {"mouthRollUpper", ""},       ArkitGroup::kMouth},
    {"mouthShrugLower",     {"mouthShrugLower", ""},      ArkitGroup::kMouth},
    {"mouthShrugUpper",     {"mouthShrugUpper", ""},      ArkitGroup::kMouth},
    {"mouthPressLeft",      {"mouthPress_L", ""},         ArkitGroup::kMouth},
    {"mouthPressRight",     {"mouthPress_R", ""},         ArkitGroup::kMouth},
    {"mouthLowerDownLeft",  {"mouthLowerDown_L", ""},     ArkitGroup::kMouth},
    {"mouthLowerDownRight", {"mouthLowerDown_R", ""},     ArkitGroup::kMouth},
    {"mouthUpperUpLeft",    {"mouthUpperUp_L", ""},       ArkitGroup::kMouth},
    {"mouthUpperUpRight",   {"mouthUpperUp_R", ""},       ArkitGroup::kMouth},
    {"browDownLeft",        {"browDown_L", ""},           ArkitGroup::kBrow},
    {"browDownRight",       {"browDown_R", ""},           ArkitGroup::kBrow},
    {"browInnerUp",         {"browInnerUp_L", "browInnerUp_R"}, ArkitGroup::kBrow},
    {"browOuterUpLeft",     {"browOuterUp_L", ""},        ArkitGroup::kBrow},
    {"browOuterUpRight",    {"browOuterUp_R", ""},        ArkitGroup::kBrow},
    {"cheekPuff",           {"cheekPuff_L", "cheekPuff_R"},     ArkitGroup::kMouth},
    {"cheekSquintLeft",     {"cheekSquint_L", ""},        ArkitGroup::kMouth},
    {"cheekSquintRight",    {"cheekSquint_R", ""},        ArkitGroup::kMouth},
    {"noseSneerLeft",       {"noseSneer_L", ""},          ArkitGroup::kMouth},
    {"noseSneerRight",      {"noseSneer_R", ""},          ArkitGroup::kMouth},
    {"tongueOut",           {"", ""},                     ArkitGroup::kTongue},
}};
// clang-format on

// Index of a shape by its ARKit name (exact, case-sensitive); nullopt when it is not one.
std::optional<std::size_t> arkit_index(std::string_view name);

// The Live Link Face CSV spelling: the name with its first letter upper case ("JawOpen").
std::string live_link_name(std::string_view arkit_name);

}  // namespace fapcast
