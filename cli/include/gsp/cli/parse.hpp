#pragma once
// Parsing of option values that CLI11 has no type for. Every function throws
// gsp::cli::UsageError (exit code 2) with a message naming the option, the text given and
// what was expected, e.g.
//   --source-vertex: "1,x,3": "x" is not a vertex index (a non-negative integer)
// Take the option as a std::string (or a std::vector<std::string> for repeatable options)
// in CLI11 and convert it in the body:
//
//   std::vector<std::string> vertex_args;
//   app.add_option("--source-vertex", vertex_args, "...")->type_name("I[,J,...]");
//   ...
//   for (auto& a : vertex_args) for (Index v : gsp::cli::parse_index_list(a, "--source-vertex")) ...
#include <gsp/io/mesh_io.hpp>
#include <gsp/surface_point.hpp>
#include <gsp/types.hpp>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace gsp::cli {

// "1,2,3" (spaces around items allowed) -> {1, 2, 3}. Empty items and non-integers are errors.
std::vector<Index> parse_index_list(std::string_view text, std::string_view option);

// "0.5,-1,2e-3" -> finite doubles (NaN and infinities are errors).
std::vector<double> parse_number_list(std::string_view text, std::string_view option);

// "x,y,z" -> a finite point.
Vec3 parse_vec3(std::string_view text, std::string_view option);

// A point inside a face: "F:u,v" with F a face index and (u, v) the barycentric weights of
// the face's corners 1 and 2; corner 0 gets 1 - u - v, clamped at 0 (u + v may pass 1 by the
// tolerance). Requires u >= 0, v >= 0, u + v <= 1 (up to 1e-9). Whether F exists is checked
// against the mesh later (SurfacePoint::exists_in, gsp::InvalidInput).
SurfacePoint parse_face_point(std::string_view text, std::string_view option);

// A finite double (for options that must be finite but are given as strings).
double parse_number(std::string_view text, std::string_view option);

// The format of an output path by its extension; a UsageError names the accepted extensions
// when it is not one of `allowed`. Call it before the work so a typo costs nothing.
io::Format output_format(const std::string& path, std::initializer_list<io::Format> allowed,
                         std::string_view option = "-o");

}  // namespace gsp::cli
