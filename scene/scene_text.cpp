// Text helpers of the scene loader: error construction, number formatting, suggestions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "scene/scene_internal.h"
#include "scene/scene_loader.h"

namespace porosph::scene {
namespace {

std::string error_text(const std::string& file, int line, const std::string& key,
                       const std::string& message) {
  std::string out = file;
  if (line > 0) out += ":" + std::to_string(line);
  out += ": ";
  if (!key.empty()) out += "key '" + key + "': ";
  return out + message;
}

/// Levenshtein distance (insertions, deletions, substitutions).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({above + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

SceneError::SceneError(std::string file, int line, std::string key, const std::string& message)
    : std::runtime_error(error_text(file, line, key, message)),
      file_(std::move(file)),
      line_(line),
      key_(std::move(key)) {}

void ErrorContext::fail(const toml::node* node, const std::string& key,
                        const std::string& message) const {
  const toml::source_path_ptr path = node ? node->source().path : nullptr;
  if (path && *path == kOverrideSource) throw SceneError(kOverrideSource, 0, key, message);
  const int line = (path && *path == file_) ? static_cast<int>(node->source().begin.line) : 0;
  throw SceneError(file_, line, key, message);
}

std::string format_number(double value) {
  // Start with enough digits for the integer part, so 60 prints as "60", not "6e+01".
  const double magnitude = std::fabs(value);
  const int integer_digits = (magnitude >= 1.0 && std::isfinite(magnitude))
                                 ? static_cast<int>(std::log10(magnitude)) + 1
                                 : 1;
  char buffer[32];
  for (int precision = std::min(integer_digits, 17); precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

std::string node_type_phrase(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    default:
      return "nothing";
  }
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates,
                         const std::string& prefix) {
  const std::size_t tolerance = std::max<std::size_t>(1, std::min<std::size_t>(3, word.size() / 3));
  const std::string* best = nullptr;
  std::size_t best_distance = tolerance + 1;
  for (const auto& candidate : candidates) {
    const std::size_t d = edit_distance(word, candidate);
    if (d < best_distance) {
      best_distance = d;
      best = &candidate;
    }
  }
  return best ? " (did you mean '" + prefix + *best + "'?)" : std::string();
}

std::string quoted_list(const std::vector<std::string>& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i)
    out += (i == 0 ? "'" : (i + 1 == values.size() ? " or '" : ", '")) + values[i] + "'";
  return out;
}

const char* axis_name(std::size_t axis) { return axis == 0 ? "x" : (axis == 1 ? "y" : "z"); }

std::string join_key(const std::string& parent, const std::string& name) {
  return parent.empty() ? name : parent + "." + name;
}

NodePtr parse_toml_value(const std::string& text, const std::string& source) {
  toml::table holder;
  try {
    holder = toml::parse("v = " + text + "\n", source);
  } catch (const toml::parse_error&) {
    return nullptr;
  }
  toml::node* value = holder.get("v");
  if (holder.size() != 1 || value == nullptr) return nullptr;
  // Move (not copy) so the node keeps its source region, which names `source` in errors.
  return value->visit([](auto& concrete) -> NodePtr {
    using Concrete = std::remove_reference_t<decltype(concrete)>;
    return NodePtr(new Concrete(std::move(concrete)));
  });
}

}  // namespace porosph::scene
