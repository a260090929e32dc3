#pragma once
// Shared by the OBJ readers (read_obj.cpp serial, read_obj_parallel.cpp on several threads):
// what is collected besides the geometry, and the checks and conversions at the end.
#include <gsp/io/mesh_io.hpp>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace gsp::io::detail {

struct ObjExtras {
  std::vector<std::array<double, 3>> colors;   // as read; kept only if every vertex has one
  bool all_colored = true;
  long long max_index = -1;          // largest resolved index, checked once all vertices are known
  std::size_t max_index_line = 0;
  std::map<std::string, std::size_t> skipped;   // keyword -> count, reported as notes
};

// Counts, the out-of-range check, colours and notes: the end of reading an OBJ file.
void finish_obj(const std::string& path, ObjExtras& extras, ReadResult& r);

// The OBJ text read on `threads` threads into `r` (empty); false, with `r` in any state, at
// the first irregularity (the serial reader then reads the file and names the error).
bool read_obj_parallel(const std::string& bytes, unsigned threads, ReadResult& r);

}  // namespace gsp::io::detail
