// Command-line overrides: "a.b=value" applied to the parsed scene before validation.
//
// The value is read as a TOML value (0.005, [0.1, 0.2], true, "text"); anything else (and any
// non-string given for a string key) is taken as a bare string. Elements of an array of tables are
// addressed as walls.1.max or walls[1].max (0-based). The key must exist in the schema.
#include <cctype>
#include <cstdio>

#include "scene/scene_internal.h"
#include "scene/scene_loader.h"

namespace porosph::scene {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

/// One step of a key path: a name or an array index.
struct Segment {
  std::string name;
  long index = -1;  ///< >= 0: an array index
};

bool all_digits(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

/// "walls[1].max" or "walls.1.max" -> {walls, 1, max}. Returns false on malformed text.
bool split_key(const std::string& key, std::vector<Segment>& segments) {
  std::string current;
  auto flush = [&]() {
    if (current.empty()) return false;
    segments.push_back(all_digits(current) ? Segment{"", std::stol(current)}
                                           : Segment{current, -1});
    current.clear();
    return true;
  };
  for (std::size_t i = 0; i < key.size(); ++i) {
    const char c = key[i];
    if (c == '.') {
      if (!current.empty() && !flush()) return false;
      if (i + 1 == key.size() || key[i + 1] == '.' || i == 0) return false;
    } else if (c == '[') {
      const auto close = key.find(']', i);
      if (!flush() || close == std::string::npos || !all_digits(key.substr(i + 1, close - i - 1)))
        return false;
      segments.push_back({"", std::stol(key.substr(i + 1, close - i - 1))});
      i = close;
      if (i + 1 < key.size() && key[i + 1] != '.' && key[i + 1] != '[') return false;
    } else {
      current += c;
    }
  }
  if (!current.empty()) flush();
  return !segments.empty();
}

/// `text` as a TOML basic string literal.
std::string quote(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '\\' || c == '"') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", c);
      out += escape;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

/// The override's value as a node whose source is "--set".
NodePtr override_value(const std::string& text, const KeySpec& spec) {
  NodePtr value = parse_toml_value(text, kOverrideSource);
  if (!value || (spec.type == ValueType::String && !value->is_string()))
    value = parse_toml_value(quote(text), kOverrideSource);
  return value;
}

[[noreturn]] void fail(const std::string& key, const std::string& message) {
  throw SceneError(kOverrideSource, 0, key, message);
}

void apply_override(toml::table& root, const std::string& assignment, const SceneSchema& schema) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos) fail(assignment, "expected key=value");
  const std::string written_key = trim(assignment.substr(0, equals));
  const std::string text = trim(assignment.substr(equals + 1));
  std::vector<Segment> segments;
  if (!split_key(written_key, segments) || segments.front().index >= 0)
    fail(written_key, "malformed key (write a.b or walls[1].max)");

  toml::table* table = &root;
  std::string schema_path;
  std::string key;  // normalised: walls[1].max
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& segment = segments[i];
    if (segment.index >= 0)
      fail(key + "[" + std::to_string(segment.index) + "]", "not an array of tables");
    const std::string path = join_key(schema_path, segment.name);
    key = join_key(key, segment.name);
    const bool last = i + 1 == segments.size();
    if (last) {
      const KeySpec* spec = schema.find_key(path);
      if (!spec) {
        const std::string parent = key.substr(0, key.size() - segment.name.size());
        fail(key,
             "unknown key" + did_you_mean(segment.name, schema.child_names(schema_path), parent));
      }
      NodePtr value = override_value(text, *spec);
      value->visit(
          [&](auto& concrete) { table->insert_or_assign(segment.name, std::move(concrete)); });
      return;
    }
    if (schema.find_table(path)) {
      if (!table->contains(segment.name)) table->insert(segment.name, toml::table{});
      table = table->get(segment.name)->as_table();
      if (!table) fail(key, "the scene has a value here, not a table");
      schema_path = path;
    } else if (const TableSpec* array_spec = schema.find_table(path + "[]")) {
      if (segments[i + 1].index < 0)
        fail(key, "an array of tables: address an entry as " + key + "[0]." + segments[i + 1].name);
      const long index = segments[++i].index;
      toml::array* array = table->get_as<toml::array>(segment.name);
      const long count = array ? static_cast<long>(array->size()) : 0;
      key += "[" + std::to_string(index) + "]";
      if (index >= count || !array->get(index)->is_table())
        fail(key, "no such entry: the scene has " + std::to_string(count) + " [[" +
                      array_spec->header_name() + "]] entries (indices start at 0)");
      table = array->get(index)->as_table();
      schema_path = path + "[]";
      if (i + 1 == segments.size())
        fail(key, "an entry of an array of tables: name one of its keys");
    } else {
      const std::string parent = key.substr(0, key.size() - segment.name.size());
      fail(key,
           "unknown key" + did_you_mean(segment.name, schema.child_names(schema_path), parent));
    }
  }
}

}  // namespace

void apply_overrides(toml::table& root, const std::vector<std::string>& overrides,
                     const SceneSchema& schema) {
  for (const auto& assignment : overrides) apply_override(root, assignment, schema);
}

}  // namespace porosph::scene
