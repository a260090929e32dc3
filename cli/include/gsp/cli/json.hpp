#pragma once
// A small JSON value for the apps' machine-readable output (--stats, gsp-info --json).
//
// Objects keep their keys in insertion order, so a report reads in the order it was built.
// Doubles are written with %.17g precision, shortened to %.15g or %.16g when that reads back
// bit-identical too (0.1 prints as 0.1, 1/3 keeps 17 digits); NaN and infinities, which
// JSON cannot express, are written as null. Strings are escaped per RFC 8259 (quotes,
// backslashes, control characters as \uXXXX; other bytes are passed through as UTF-8).
//
//   gsp::cli::Json stats;                       // null; becomes an object on first key
//   stats["input"]["vertices"] = 4494;
//   stats["timings"]["read"] = 0.012;
//   stats["settings"]["weld"] = true;
//   auto& list = stats["sources"] = gsp::cli::Json::array();
//   list.push_back(17);
//   std::string text = stats.dump();            // pretty-printed, 2-space indent
#include <cstdint>
#include <list>
#include <string>
#include <string_view>
#include <vector>

namespace gsp::cli {

class Json {
 public:
  enum class Type { null, boolean, integer, unsigned_integer, number, string, array, object };

  Json() = default;  // null
  Json(std::nullptr_t) {}
  Json(bool b) : type_(Type::boolean), bool_(b) {}
  Json(int i) : type_(Type::integer), int_(i) {}
  Json(long i) : type_(Type::integer), int_(i) {}
  Json(long long i) : type_(Type::integer), int_(i) {}
  Json(unsigned u) : type_(Type::unsigned_integer), uint_(u) {}
  Json(unsigned long u) : type_(Type::unsigned_integer), uint_(u) {}
  Json(unsigned long long u) : type_(Type::unsigned_integer), uint_(u) {}
  Json(double d) : type_(Type::number), double_(d) {}
  Json(float f) : type_(Type::number), double_(f) {}
  Json(const char* s) : type_(Type::string), string_(s) {}
  Json(std::string s) : type_(Type::string), string_(std::move(s)) {}
  Json(std::string_view s) : type_(Type::string), string_(s) {}

  static Json array() { Json j; j.type_ = Type::array; return j; }
  static Json object() { Json j; j.type_ = Type::object; return j; }
  // An array of numbers in one call (coordinates, histograms).
  template <class Range>
  static Json array_of(const Range& values) {
    Json j = array();
    for (const auto& v : values) j.push_back(Json(v));
    return j;
  }

  Type type() const { return type_; }
  bool is_null() const { return type_ == Type::null; }
  bool is_object() const { return type_ == Type::object; }
  bool is_array() const { return type_ == Type::array; }

  // Object member, inserted (as null) when missing. A null value turns into an empty object
  // first; any other non-object type is a programming error (std::logic_error).
  // References to members stay valid while other members are added (node storage).
  Json& operator[](std::string_view key);
  // Object member or nullptr (no insertion).
  const Json* find(std::string_view key) const;
  // Appends to an array (a null value turns into an empty array first).
  Json& push_back(Json value);
  // Number of members (object) or elements (array); 0 otherwise.
  std::size_t size() const;

  // Serialise. indent < 0: one line with no spaces; otherwise pretty with that indent.
  std::string dump(int indent = 2) const;

 private:
  void write(std::string& out, int indent, int depth) const;

  Type type_ = Type::null;
  bool bool_ = false;
  std::int64_t int_ = 0;
  std::uint64_t uint_ = 0;
  double double_ = 0.0;
  std::string string_;
  std::vector<std::string> keys_;   // object keys, parallel to items_
  std::list<Json> items_;           // object values or array elements; a list so that
                                    // references handed out stay valid as members are added
};

// The building blocks, for code that streams JSON itself.
// Appends s as a quoted, escaped JSON string.
void append_json_string(std::string& out, std::string_view s);
// Appends d so that it reads back bit-identical (see above), or null when d is not finite.
void append_json_number(std::string& out, double d);

}  // namespace gsp::cli
