#pragma once
// Line-oriented reading of synth data files (meshes, targets, spec tables), with size limits.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace fapcast::synth {

// Opens `file` for reading; throws DataFileError (line 0) when it is missing, unreadable or
// larger than max_bytes.
std::ifstream open_data_file(const std::filesystem::path& file, std::uintmax_t max_bytes);

// Reads the next line that is neither blank nor a '#' comment into `line` (CR stripped),
// counting every line read in `line_number`; false at the end of the stream.
bool next_content_line(std::istream& in, std::string& line, std::size_t& line_number);

}  // namespace fapcast::synth
