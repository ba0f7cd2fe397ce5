// Files read and written by the front ends: text read whole, and output files written whole or
// not at all.
#pragma once

#include <string>

namespace hinf {

// The whole content of a file; InputError "cannot read <what> '<path>': <reason>" for a file
// that cannot be read (missing, a directory, a read error).
std::string read_text_file(const std::string& path, const std::string& what);

// Checks, before any computation, that an output file can be written at path: not empty,
// not a directory, and the nearest existing folder above it is a writable folder (missing
// folders are created by write_text_file). InputError naming the path otherwise.
void check_output_path(const std::string& path);
// Writes a file whole or not at all: a temporary file in the same folder, renamed over path
// once complete (an existing device or pipe, such as /dev/stdout, is written in place).
// Creates missing folders. InputError naming the path on any failure (a full disk included).
void write_text_file(const std::string& path, const std::string& text);

}  // namespace hinf
