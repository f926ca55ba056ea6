// Reading a whole input file into memory for the text readers.
// [OGC06-103 §7] [RFC7946] (the formats the contents are read as)
// Preconditions: none; unusable paths throw mk::InvalidInput.
#pragma once

#include <string>
#include <string_view>

namespace mk {

// The file's bytes. Throws mk::InvalidInput for an empty path ("no input file given"), a
// directory ("'<path>' is a directory, not a file") and a file that cannot be opened or
// read ("cannot open '<path>': <reason>"). An empty file gives "": whether that is an
// error is the caller's decision (see empty_input_message).
std::string read_file(const std::string& path);

// The message for an input that has no content: "'<path>' is empty: expected a polygon in
// WKT, GeoJSON or native JSON (an empty polygon is written POLYGON EMPTY)".
std::string empty_input_message(std::string_view path);

}  // namespace mk
