#pragma once
// One reader per format (read_<format>.cpp); read_mesh() in mesh_io.cpp picks one by extension.
// Each gets the whole file in memory (`bytes`, never empty) and the path for error messages;
// the PLY and OBJ readers also get the threads they may use (text_pieces.hpp).
#include <gsp/io/mesh_io.hpp>

#include <string>

namespace gsp::io::detail {

ReadResult read_obj(const std::string& path, const std::string& bytes, unsigned threads);
ReadResult read_ply(const std::string& path, const std::string& bytes, unsigned threads);
ReadResult read_off(const std::string& path, const std::string& bytes);
ReadResult read_stl(const std::string& path, const std::string& bytes);
ReadResult read_xyz(const std::string& path, const std::string& bytes);
ReadResult read_gltf(const std::string& path, const std::string& bytes, bool binary);

}  // namespace gsp::io::detail
