#pragma once
// Polylines as text, for --source-polyline (parsing only: the caller reads the file).
//
// Two formats, told apart by the content:
//  - OBJ: `v x y z` lines and `l i j k ...` elements (1-based, negative = relative, as OBJ
//    says); each `l` element is one polyline. Other OBJ statements are ignored.
//  - Plain points: one "x y z" per line (spaces, tabs or commas); a blank line ends a
//    polyline and starts the next.
// Lines starting with '#' are comments. A polyline is closed by repeating its first point as
// its last (OBJ: `l 1 2 3 1`).
#include <gsp/lines/line_source.hpp>

#include <string>
#include <vector>

namespace gsp::lines {

// Throws IoError(file_name, "line N", what) for malformed lines, non-finite numbers, bad
// indices, a polyline of one point, or a text with no polyline at all.
std::vector<Polyline> parse_polylines(const std::string& text, const std::string& file_name);

}  // namespace gsp::lines
