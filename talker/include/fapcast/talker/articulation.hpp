#pragma once
// The reference talker's articulation (SYNTHETIC): per phone and articulatory channel a target
// and a Cohen-Massaro dominance function (spec/articulation.tsv), and the map from channel values
// to ICT expression-shape weights (spec/articulation_shapes.tsv).
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fapcast/face/face_model.hpp"
#include "fapcast/math/dominance.hpp"
#include "fapcast/phonetics/phone.hpp"

namespace fapcast {

// Articulatory channels; each carries a value in [0, 1].
enum class Channel : std::uint8_t {
  jaw,          // jaw opening (0 closed, 1 = ICT jawOpen fully on)
  lip_opening,  // lips parted beyond what the jaw gives
  rounding,     // rounding / protrusion
  spreading,    // spreading (stretch, smile)
  closure,      // bilabial closure: 1 = lips pressed together
  labiodental,  // lower lip against the upper teeth
  tongue_tip,   // tip raised to the alveolar ridge / teeth (1 = contact)
  tongue_body,  // dorsum raised towards the palate (1 = velar contact)
};
inline constexpr std::size_t kChannelCount = 8;

// "jaw", "lip_opening", ... as in spec/articulation.tsv.
std::string_view channel_name(Channel channel);
// Inverse of channel_name; throws std::invalid_argument naming the unknown name.
Channel channel_from_name(std::string_view name);

// One row of the articulation table.
struct PhoneChannelTarget {
  std::string_view phone;  // ARPAbet without stress digit, or "sil"
  Channel channel;
  float target;            // in [0, 1]
  Dominance dominance;
};

// The whole table, phone-major, kChannelCount rows per phone (spec/articulation.tsv order).
std::span<const PhoneChannelTarget> articulation_table();

// A phone's targets and dominances, indexed by Channel.
struct PhoneArticulation {
  std::array<float, kChannelCount> target;
  std::array<Dominance, kChannelCount> dominance;
};

// The 40 phone symbols of the table (39 ARPAbet + "sil").
std::vector<std::string_view> articulation_phones();

// A phone's articulation; a trailing stress digit ("AH0") is ignored, "" and "sp"/"pau" are
// silence. Throws std::invalid_argument naming an unknown symbol.
const PhoneArticulation& phone_articulation(std::string_view phone);
// The same for a Phone (SIL: "sil").
const PhoneArticulation& phone_articulation(Phone phone);

// One row of the channel -> expression-shape map.
struct ChannelShapeRow {
  Channel channel;
  std::string_view shape;           // ICT expression name
  float weight;
  std::optional<Channel> scale_by;  // also multiplied by this channel's value
  bool gated;                       // multiplied by (1 - closure) * (1 - labiodental)
};
std::span<const ChannelShapeRow> channel_shape_table();

// Channel values -> ICT expression weights for one face (weights clamped to [0, 1]).
class ShapeMapper {
 public:
  explicit ShapeMapper(const FaceModel& face);  // throws if a shape is missing from the face
  // One weight per face expression shape.
  std::vector<float> operator()(const std::array<float, kChannelCount>& channels) const;
  std::size_t shape_count() const { return shape_count_; }

 private:
  std::size_t shape_count_;
  std::vector<std::size_t> shape_of_row_;  // per channel_shape_table() row
};

// Jaw opening angle of the talker for a jaw channel value: value * 0.35 rad (ICT jawOpen = 1
// taken as a 20 degree opening; the speech targets stay at or below 0.3).
double jaw_opening_angle_rad(float jaw);

// spec/articulation.tsv as read from disk (7 columns).
struct ArticulationSpecRow {
  std::string phone;
  std::string channel;
  float target, alpha, theta_before, theta_after, c;
};
std::vector<ArticulationSpecRow> read_articulation_spec(const std::filesystem::path& file);

// spec/articulation_shapes.tsv as read from disk (5 columns).
struct ChannelShapeSpecRow {
  std::string channel, shape;
  float weight;
  std::string scale_by;  // "-" = none
  bool gated;
};
std::vector<ChannelShapeSpecRow> read_channel_shape_spec(const std::filesystem::path& file);

}  // namespace fapcast
