#pragma once
// The category of a corpus mesh (benign / malign / unknown), read from the SOURCES.md that
// the shared data folders keep beside their files: a markdown table with a `File` column
// (the file name in backticks) and a `Character` column whose first word is "benign" or
// "malign". The corpus report aggregates per category, so a regression on the hard (malign)
// meshes is not averaged away by the easy ones.
#include <map>
#include <string>

namespace gsp::bench {

// The category of `file_name` in the markdown `text`: "benign", "malign" or "unknown" (no
// such row, no such table, another first word).
std::string category_in(const std::string& text, const std::string& file_name);

// Looks meshes up in the SOURCES.md beside each one, or in one named file for all
// (--categories FILE; gsp::IoError if it cannot be read). Each file is read once.
class Categories {
 public:
  explicit Categories(const std::string& file = "");
  std::string of(const std::string& mesh_path);

 private:
  const std::string& text_for(const std::string& mesh_path);
  bool fixed_ = false;
  std::string fixed_text_;
  std::map<std::string, std::string> by_folder_;   // folder -> its SOURCES.md ("" if none)
};

}  // namespace gsp::bench
