// Reading a whole input file into memory for the text readers.
// [OGC06-103 §7] [RFC7946] (the formats the contents are read as)
// Preconditions: none; unusable paths throw mk::InvalidInput.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace mk {

// The file's bytes. Throws mk::InvalidInput for an empty path ("no input file given"), a
// directory ("'<path>' is a directory, not a file") and a file that cannot be opened or
// read ("cannot open '<path>': <reason>"). An empty file gives "": whether that is an
// error is the caller's decision (see empty_input_message).
std::string read_file(const std::string& path);

// As read_file, for an input that must be text (a polygon in WKT, GeoJSON or native JSON,
// none of which ever holds a NUL byte): reading stops at the first NUL byte and throws
// mk::InvalidInput ("'<path>' holds a NUL byte at offset N: binary data, not WKT, GeoJSON
// or JSON text"), so /dev/zero, /dev/urandom or a binary file is refused after one read
// instead of being read to its end, or until memory runs out.
std::string read_text_file(const std::string& path);

// Reads the stream to its end, as read_text_file does (name is how messages call it, e.g.
// "standard input"). Throws mk::InvalidInput at a NUL byte or a read error.
std::string read_text_stream(std::FILE* stream, const std::string& name);

// The message for an input that has no content: "'<path>' is empty: expected a polygon in
// WKT, GeoJSON or native JSON (an empty polygon is written POLYGON EMPTY)".
std::string empty_input_message(std::string_view path);

}  // namespace mk
