#pragma once
// Which syntax an FBA stream follows, and how its start-code emulation prevention is read
// (spec/fba.md §2, §9).
namespace fapcast {

// The standard syntax (ISO/IEC 14496-2 FBA, FAP predictive coding), or fapcast's own profile,
// signalled in a file's first bytes (user data "fapcast" instead of the object start code) and in
// the RTP payload header.
enum class FbaProfile { kStandard, kFapcast };
const char* fba_profile_name(FbaProfile p);  // "standard FBA", "fapcast profile"

// Where the stuffed 1 after 22 zeros applies (spec/fba.md §2):
// - kReference (the standard syntax as the published codec codes it): only the bits of
//   arithmetic-coded segments count and are stuffed; the count restarts at every segment; the 1
//   is written before the coded bit that would be the 23rd zero.
// - kContinuous (the fapcast profile; a second reading of the standard): every bit after a start
//   code counts, and the 1 follows the 22nd zero at once, wherever it falls.
enum class FbaStuffing { kReference, kContinuous };

}  // namespace fapcast
