#include <gsp/cli/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace gsp::cli {

Json& Json::operator[](std::string_view key) {
  if (type_ == Type::null) type_ = Type::object;
  if (type_ != Type::object) throw std::logic_error("Json: operator[] on a non-object");
  // Linear search: reports have a handful of keys per object, and order must be kept.
  auto item = items_.begin();
  for (std::size_t i = 0; i < keys_.size(); ++i, ++item)
    if (keys_[i] == key) return *item;
  keys_.emplace_back(key);
  items_.emplace_back();
  return items_.back();
}

const Json* Json::find(std::string_view key) const {
  if (type_ != Type::object) return nullptr;
  auto item = items_.begin();
  for (std::size_t i = 0; i < keys_.size(); ++i, ++item)
    if (keys_[i] == key) return &*item;
  return nullptr;
}

Json& Json::push_back(Json value) {
  if (type_ == Type::null) type_ = Type::array;
  if (type_ != Type::array) throw std::logic_error("Json: push_back on a non-array");
  items_.push_back(std::move(value));
  return items_.back();
}

std::size_t Json::size() const {
  return (type_ == Type::array || type_ == Type::object) ? items_.size() : 0;
}

void append_json_string(std::string& out, std::string_view s) {
  out += '"';
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20 || c == 0x7f) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  out += '"';
}

void append_json_number(std::string& out, double d) {
  if (!std::isfinite(d)) {
    out += "null";
    return;
  }
  // The shortest of %.15g, %.16g, %.17g that reads back bit-identical: as exact as %.17g
  // (which always round-trips) without printing 0.1 as 0.10000000000000001.
  char buf[32];
  for (int precision = 15; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, d);
    if (precision == 17 || std::strtod(buf, nullptr) == d) break;
  }
  out += buf;
}

namespace {
void newline(std::string& out, int indent, int depth) {
  if (indent < 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent * depth), ' ');
}
}  // namespace

void Json::write(std::string& out, int indent, int depth) const {
  switch (type_) {
    case Type::null: out += "null"; break;
    case Type::boolean: out += bool_ ? "true" : "false"; break;
    case Type::integer: out += std::to_string(int_); break;
    case Type::unsigned_integer: out += std::to_string(uint_); break;
    case Type::number: append_json_number(out, double_); break;
    case Type::string: append_json_string(out, string_); break;
    case Type::array:
    case Type::object: {
      const bool obj = type_ == Type::object;
      out += obj ? '{' : '[';
      if (items_.empty()) {
        out += obj ? '}' : ']';
        break;
      }
      // Arrays of scalars stay on one line: coordinates and small lists read better that way.
      bool flat = !obj;
      for (const Json& item : items_)
        if (item.type_ == Type::array || item.type_ == Type::object) flat = false;
      std::size_t i = 0;
      for (auto item = items_.begin(); item != items_.end(); ++item, ++i) {
        if (i) out += (flat && indent >= 0) ? ", " : ",";
        if (!flat) newline(out, indent, depth + 1);
        if (obj) {
          append_json_string(out, keys_[i]);
          out += indent >= 0 ? ": " : ":";
        }
        item->write(out, indent, depth + 1);
      }
      if (!flat) newline(out, indent, depth);
      out += obj ? '}' : ']';
      break;
    }
  }
}

std::string Json::dump(int indent) const {
  std::string out;
  write(out, indent, 0);
  return out;
}

}  // namespace gsp::cli
