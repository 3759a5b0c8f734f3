#pragma once
// Whether a language code names an installed espeak-ng language: what `say --lang` and the
// aligner's accent (`align --lang`) check before they use it.
#include <string_view>

namespace fapcast {

// Whether the installed espeak-ng lists language `code` ("en-gb"), as espeak_languages()
// (text_frontend.hpp) gives them; the list is read once per process.
bool espeak_language_installed(std::string_view code);

}  // namespace fapcast
