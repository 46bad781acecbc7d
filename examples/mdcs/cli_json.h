// A small JSON writer for the machine-readable outputs of mdcs (summary.json, paths.json, ...): objects keep
// their keys in insertion order, numbers are written with 17 significant digits (they read back to the same
// double), and a number that is not finite is written as null (JSON has no infinity; the documents say what null
// means where it can occur, e.g. an unreachable vertex).
#ifndef MDCS_CLI_JSON_H
#define MDCS_CLI_JSON_H

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mdcs_cli {

inline std::string json_number(double x)
{
  if(!std::isfinite(x)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

inline std::string json_string(const std::string& s)
{
  std::string r = "\"";
  for(unsigned char c : s) {
    switch(c) {
    case '"': r += "\\\""; break;
    case '\\': r += "\\\\"; break;
    case '\n': r += "\\n"; break;
    case '\t': r += "\\t"; break;
    case '\r': r += "\\r"; break;
    default:
      if(c < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        r += buf;
      } else {
        r += char(c); // UTF-8 passes through
      }
    }
  }
  return r + "\"";
}

// A JSON array of already encoded values, on one line.
inline std::string json_array(const std::vector<std::string>& encoded)
{
  std::string r = "[";
  for(std::size_t i = 0; i < encoded.size(); ++i) r += (i ? ", " : "") + encoded[i];
  return r + "]";
}

inline std::string json_numbers(const std::vector<double>& values)
{
  std::string r = "[";
  for(std::size_t i = 0; i < values.size(); ++i) r += (i ? "," : "") + json_number(values[i]);
  return r + "]";
}

inline std::string json_strings(const std::vector<std::string>& values)
{
  std::vector<std::string> encoded;
  for(const std::string& v : values) encoded.push_back(json_string(v));
  return json_array(encoded);
}

// An object under construction: add() keeps the order; text() indents nested objects.
class Json_object
{
public:
  Json_object& add(const std::string& key, double v) { return raw(key, json_number(v)); }
  Json_object& add(const std::string& key, int v) { return raw(key, std::to_string(v)); }
  Json_object& add(const std::string& key, long v) { return raw(key, std::to_string(v)); }
  Json_object& add(const std::string& key, long long v) { return raw(key, std::to_string(v)); }
  Json_object& add(const std::string& key, unsigned long v) { return raw(key, std::to_string(v)); }
  Json_object& add(const std::string& key, unsigned long long v) { return raw(key, std::to_string(v)); }
  Json_object& add(const std::string& key, bool v) { return raw(key, v ? "true" : "false"); }
  Json_object& add(const std::string& key, const char* v) { return raw(key, json_string(v)); }
  Json_object& add(const std::string& key, const std::string& v) { return raw(key, json_string(v)); }
  Json_object& add(const std::string& key, const Json_object& v)
  {
    entries_.push_back(Entry{key, std::string(), std::make_shared<const Json_object>(v)});
    return *this;
  }
  // An encoded value (an array from json_array(), "null", ...).
  Json_object& raw(const std::string& key, const std::string& encoded)
  {
    entries_.push_back(Entry{key, encoded, nullptr});
    return *this;
  }
  bool empty() const { return entries_.empty(); }

  std::string text(int indent = 0) const
  {
    if(entries_.empty()) return "{}";
    const std::string pad(std::size_t(indent + 2), ' ');
    std::string r = "{\n";
    for(std::size_t i = 0; i < entries_.size(); ++i) {
      const Entry& e = entries_[i];
      r += pad + json_string(e.key) + ": " + (e.object ? e.object->text(indent + 2) : e.encoded);
      r += i + 1 < entries_.size() ? ",\n" : "\n";
    }
    return r + std::string(std::size_t(indent), ' ') + "}";
  }

private:
  struct Entry
  {
    std::string key, encoded;
    std::shared_ptr<const Json_object> object;
  };
  std::vector<Entry> entries_;
};

} // namespace mdcs_cli

#endif // MDCS_CLI_JSON_H
