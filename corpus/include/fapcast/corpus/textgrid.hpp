#pragma once
// Praat TextGrid text files: read the long ("ooTextFile" with keys) and short (values only)
// forms in UTF-8 (BOM optional) or UTF-16 (LE or BE, BOM required, as Praat writes for
// non-ASCII labels); write either form in UTF-8. Rules refused are listed in spec/corpus.md.
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/alignment.hpp"

#include <string>
#include <string_view>

namespace fapcast {

enum class TextGridForm { long_form, short_form };

// Parses a TextGrid file's bytes. Throws InputError ("name:line: textgrid-...: detail").
Alignment read_textgrid(std::string_view bytes, const std::string& source);

// The TextGrid text of `alignment` in UTF-8 without BOM, "" doubled inside strings, times in
// the shortest decimal that reads back exactly. Throws std::invalid_argument if the alignment
// breaks a TextGrid invariant (the reader's rules), so the writer never emits a file it refuses.
std::string write_textgrid(const Alignment& alignment, TextGridForm form = TextGridForm::long_form);

}  // namespace fapcast
