#include "fapcast/fba/fba_profile.hpp"

namespace fapcast {

const char* fba_profile_name(FbaProfile p) { return p == FbaProfile::kStandard ? "standard FBA" : "fapcast profile"; }

}  // namespace fapcast
