// Choosing the input format of a polygon file (WKT, GeoJSON or native JSON) and reading it
// into the paper's polygon model. [OGC06-103 §7] [RFC7946] [MK89 §2.2]
// Preconditions: none; unreadable input throws mk::InvalidInput.
#pragma once

#include <string_view>

#include "core/polygon.hpp"

namespace mk {

enum class Format { wkt, geojson, native_json };

// "WKT", "GeoJSON", "native JSON": the names used in messages.
std::string_view format_name(Format format);

// By the file name's extension when it has one of .wkt, .geojson or .json (any case); a
// .json file whose top-level object has a "rings" member is native JSON, any other
// GeoJSON. Without a known extension, by the content: text starting with '{' is JSON as
// above, anything else WKT. The content scan stops early and copies nothing.
Format sniff_format(std::string_view text, std::string_view filename_hint);

// Reads a polygon in the sniffed format. WKT and GeoJSON give one island-type polygon whose
// rings are the shells and holes (their nesting decides their role) [MK89 §2.2].
Polygon read_polygon(std::string_view text, std::string_view filename_hint);

}  // namespace mk
