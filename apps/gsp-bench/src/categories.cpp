#include "categories.hpp"

#include <gsp/errors.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace gsp::bench {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// "| a | b |" -> {"", "a", "b", ""}: the same positions in the header and in every row.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (char c : line) {
    if (c == '|') out.push_back(trim(cell)), cell.clear();
    else cell += c;
  }
  out.push_back(trim(cell));
  return out;
}

int column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return int(i);
  return -1;
}

bool read_text(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  return true;
}

}  // namespace

std::string category_in(const std::string& text, const std::string& file_name) {
  const std::string wanted = "`" + file_name + "`";
  int file_col = -1, character_col = -1;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (trim(line).rfind('|', 0) != 0) {   // a table ends at the first line that is not a row
      file_col = character_col = -1;
      continue;
    }
    const std::vector<std::string> row = cells(trim(line));
    if (file_col < 0) {   // the header of a table: does it have the two columns?
      file_col = column(row, "File"), character_col = column(row, "Character");
      if (character_col < 0) file_col = -1;
      continue;
    }
    if (int(row.size()) <= std::max(file_col, character_col) || row[std::size_t(file_col)] != wanted) continue;
    const std::string& character = row[std::size_t(character_col)];
    const std::string first = character.substr(0, character.find_first_of(" (,;"));
    return first == "benign" || first == "malign" ? first : "unknown";
  }
  return "unknown";
}

Categories::Categories(const std::string& file) : fixed_(!file.empty()) {
  if (fixed_ && !read_text(file, fixed_text_)) throw IoError(file, "", "cannot read the categories file");
}

const std::string& Categories::text_for(const std::string& mesh_path) {
  if (fixed_) return fixed_text_;
  const std::string folder = std::filesystem::path(mesh_path).parent_path().string();
  auto it = by_folder_.find(folder);
  if (it == by_folder_.end()) {
    std::string text;
    read_text((std::filesystem::path(folder.empty() ? "." : folder) / "SOURCES.md").string(), text);
    it = by_folder_.emplace(folder, std::move(text)).first;
  }
  return it->second;
}

std::string Categories::of(const std::string& mesh_path) {
  return category_in(text_for(mesh_path), std::filesystem::path(mesh_path).filename().string());
}

}  // namespace gsp::bench
