// Schema-driven validation: every table and key of a parsed scene is checked against the schema
// (unknown keys, types, vector lengths, ranges, allowed values, required keys), and defaults are
// filled in so the typed Scene and the resolved TOML can be read without further checks. Optional
// keys left out stay out; derived defaults follow the rules in derived_default().
#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "scene/scene_internal.h"

namespace porosph::scene {
namespace {

/// The largest magnitude of an integer key (it must fit the int of the typed scene).
constexpr double kIntLimit = 2147483647.0;

bool is_number(const toml::node& n) { return n.is_integer() || n.is_floating_point(); }

bool matches_format(const std::string& text, StringFormat format) {
  if (format == StringFormat::Any) return true;
  if (text.empty() || std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-')
    return false;
  return std::all_of(text.begin(), text.end(), [format](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' ||
           (format == StringFormat::Name && c == '-');
  });
}

/// The phases whose table the scene has (a non-table there is reported by the validator).
std::vector<std::string> phases_in(const toml::table& root) {
  std::vector<std::string> present;
  for (const char* phase : kPhaseNames)
    if (root.get_as<toml::table>(phase)) present.emplace_back(phase);
  return present;
}

/// The default of a Derived key, in TOML syntax, from the phases the scene has. Every Derived key
/// of the schema needs a rule here (the scene tests load every one).
std::string derived_default(const KeySpec& spec, const std::vector<std::string>& phases) {
  if (spec.path == "walls[].phases") {
    std::string list = "[";
    for (std::size_t i = 0; i < phases.size(); ++i)
      list += (i == 0 ? "\"" : ", \"") + phases[i] + "\"";
    return list + "]";
  }
  if (spec.path == "run.c_a") return phases.size() > 1 ? "0.005" : "0.25";
  if (spec.path == "observables[].phase")
    return "\"" + (phases.empty() ? std::string("water") : phases.front()) + "\"";
  throw std::logic_error("scene schema: no rule for the derived default of " + spec.path);
}

/// Walks the scene table by table. One instance per validation; holds no state beyond it.
class Validator {
 public:
  Validator(const SceneSchema& schema, const ErrorContext& errors, int dimension,
            std::vector<std::string> phases = {})
      : schema_(schema), errors_(errors), dimension_(dimension), phases_(std::move(phases)) {}

  /// Validates `table` (schema path `schema_path`, concrete key `key`) and everything inside.
  void table(toml::table& table, const std::string& schema_path, const std::string& key) {
    for (auto& [name, node] : entries_by_line(table)) entry(*node, schema_path, key, name);
    fill_keys(table, schema_path, key);
    check_required_tables(table, schema_path, key);
  }

  /// Checks one key's value against its spec (type, length, range, allowed values).
  void value(const toml::node& node, const KeySpec& spec, const std::string& key) const {
    switch (spec.type) {
      case ValueType::Int:
        if (!node.is_integer()) expected(node, key, "an integer");
        number_in_range(node, spec, key, "");
        break;
      case ValueType::Float:
        if (!is_number(node)) expected(node, key, "a float");
        number_in_range(node, spec, key, "");
        break;
      case ValueType::Bool:
        if (!node.is_boolean()) expected(node, key, "a boolean");
        break;
      case ValueType::String:
        if (!node.is_string()) expected(node, key, "a string");
        string_value(node, spec, key, "");
        break;
      case ValueType::Vector:
        vector(node, spec, key, "");
        break;
      case ValueType::BoolVector:
        vector(node, spec, key, "");
        break;
      case ValueType::VectorList: {
        const toml::array* list = list_of(node, spec, key, "a list of vectors");
        for (std::size_t i = 0; i < list->size(); ++i)
          vector(*list->get(i), spec, key, "entry " + std::to_string(i) + ": ");
        break;
      }
      case ValueType::StringList: {
        const toml::array* list = list_of(node, spec, key, "a list of strings");
        for (std::size_t i = 0; i < list->size(); ++i) {
          const std::string where = "entry " + std::to_string(i) + ": ";
          if (!list->get(i)->is_string())
            errors_.fail(list->get(i), key,
                         where + "expected a string, got " + node_type_phrase(*list->get(i)));
          string_value(*list->get(i), spec, key, where);
        }
        break;
      }
    }
  }

 private:
  using Entry = std::pair<std::string, toml::node*>;

  /// The table's entries in the order they appear in the file, so the first error reported is
  /// the first one a reader meets.
  static std::vector<Entry> entries_by_line(toml::table& table) {
    std::vector<Entry> entries;
    for (auto& [name, node] : table) entries.emplace_back(std::string(name.str()), &node);
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
      return a.second->source().begin.line < b.second->source().begin.line;
    });
    return entries;
  }

  void entry(toml::node& node, const std::string& schema_path, const std::string& parent_key,
             const std::string& name) {
    const std::string path = join_key(schema_path, name);
    const std::string key = join_key(parent_key, name);
    if (schema_.find_table(path)) {
      if (!node.is_table()) expected(node, key, "a table ([" + path + "])");
      table(*node.as_table(), path, key);
    } else if (const TableSpec* array_spec = schema_.find_table(path + "[]")) {
      toml::array* array = node.as_array();
      if (!array || (!array->empty() && !array->is_array_of_tables()))
        expected(node, key, "an array of tables ([[" + array_spec->header_name() + "]])");
      for (std::size_t i = 0; i < array->size(); ++i)
        table(*array->get(i)->as_table(), path + "[]", key + "[" + std::to_string(i) + "]");
    } else if (const KeySpec* spec = schema_.find_key(path)) {
      value(node, *spec, key);
    } else {
      errors_.fail(&node, key,
                   "unknown key" + did_you_mean(name, schema_.child_names(schema_path),
                                                parent_key.empty() ? "" : parent_key + "."));
    }
  }

  /// Present keys that do not apply are errors; absent keys that apply are filled or missing.
  void fill_keys(toml::table& table, const std::string& schema_path, const std::string& key) {
    for (const KeySpec& spec : schema_.keys) {
      if (spec.table() != schema_path) continue;
      const std::string name = spec.name();
      const toml::node* node = table.get(name);
      const Condition* condition = spec.applies_when ? &*spec.applies_when : nullptr;
      bool applies = true;
      if (condition) {
        const auto selector = table[condition->key].value<std::string>();
        applies = selector &&
                  std::count(condition->values.begin(), condition->values.end(), *selector) > 0;
      }
      if (node && !applies)
        errors_.fail(
            node, join_key(key, name),
            "only allowed when " + condition->key + " is " + quoted_list(condition->values));
      if (node || !applies) continue;
      const DefaultValue::Kind kind = spec.default_value.kind;
      if (kind == DefaultValue::Kind::Required)
        errors_.fail(nullptr, join_key(key, name), "required key is missing");
      if (kind == DefaultValue::Kind::Optional) continue;
      const std::string text = kind == DefaultValue::Kind::Derived
                                   ? derived_default(spec, phases_)
                                   : spec.default_value.text(dimension_);
      // Inserted as a copy, which carries no source region: errors about it name no line.
      const NodePtr fallback = parse_toml_value(text, "(default)");
      fallback->visit([&](const auto& concrete) { table.insert_or_assign(name, concrete); });
    }
  }

  void check_required_tables(const toml::table& table, const std::string& schema_path,
                             const std::string& key) const {
    for (const TableSpec& spec : schema_.tables) {
      const auto dot = spec.path.rfind('.');
      const std::string parent = dot == std::string::npos ? "" : spec.path.substr(0, dot);
      if (parent != schema_path || !spec.required) continue;
      const std::string name = spec.path.substr(parent.empty() ? 0 : dot + 1);
      if (!spec.array) {
        if (!table.get(name))
          errors_.fail(nullptr, join_key(key, name), "required table is missing");
        continue;
      }
      const std::string array_name = name.substr(0, name.size() - 2);
      const toml::array* array = table[array_name].as_array();
      if (!array || array->empty())
        errors_.fail(nullptr, join_key(key, array_name),
                     "at least one [[" + spec.header_name() + "]] entry is required");
    }
  }

  [[noreturn]] void expected(const toml::node& node, const std::string& key,
                             const std::string& what, const std::string& where = "") const {
    errors_.fail(&node, key, where + "expected " + what + ", got " + node_type_phrase(node));
  }

  const toml::array* list_of(const toml::node& node, const KeySpec& spec, const std::string& key,
                             const std::string& what) const {
    const toml::array* list = node.as_array();
    if (!list) expected(node, key, what);
    if (static_cast<int>(list->size()) < spec.min_count)
      errors_.fail(&node, key,
                   "expected at least " + std::to_string(spec.min_count) +
                       (spec.min_count == 1 ? " entry" : " entries") + ", got " +
                       std::to_string(list->size()));
    return list;
  }

  /// A Vector (numbers) or BoolVector of the expected length.
  void vector(const toml::node& node, const KeySpec& spec, const std::string& key,
              const std::string& where) const {
    const bool of_bools = spec.type == ValueType::BoolVector;
    const int length = spec.vector_length > 0 ? spec.vector_length : dimension_;
    const std::string of_what = std::to_string(length) + (of_bools ? " booleans" : " numbers");
    const toml::array* array = node.as_array();
    if (!array) expected(node, key, "a vector of " + of_what, where);
    if (static_cast<int>(array->size()) != length)
      errors_.fail(
          &node, key,
          where + "expected " + std::to_string(length) + " components" +
              (spec.vector_length > 0 ? std::string()
                                      : " (run.dimension = " + std::to_string(dimension_) + ")") +
              ", got " + std::to_string(array->size()));
    for (std::size_t i = 0; i < array->size(); ++i) {
      const toml::node& component = *array->get(i);
      const std::string at = where + "component " + std::to_string(i) + ": ";
      if (of_bools ? !component.is_boolean() : !is_number(component))
        expected(component, key, of_bools ? "a boolean" : "a number", at);
      if (!of_bools) number_in_range(component, spec, key, at);
    }
  }

  void number_in_range(const toml::node& node, const KeySpec& spec, const std::string& key,
                       const std::string& where) const {
    const double v = node.value<double>().value_or(0.0);
    if (!std::isfinite(v)) {  // TOML allows nan and inf; no key means either (issue 29)
      errors_.fail(&node, key, where + "must be a finite number, got " + format_number(v));
      return;
    }
    // The typed scene holds integer keys in an int (max_steps: a long); a TOML integer is 64-bit.
    if (spec.type == ValueType::Int && std::fabs(v) > kIntLimit) {
      errors_.fail(&node, key,
                   where + "must be at most " + format_number(kIntLimit) + " in magnitude, got " +
                       format_number(v));
      return;
    }
    const bool below =
        spec.min && (spec.min->inclusive ? v < spec.min->value : v <= spec.min->value);
    const bool above =
        spec.max && (spec.max->inclusive ? v > spec.max->value : v >= spec.max->value);
    if (!below && !above) return;
    std::string range;
    if (spec.min && spec.max)
      range = "in " + std::string(spec.min->inclusive ? "[" : "(") +
              format_number(spec.min->value) + ", " + format_number(spec.max->value) +
              (spec.max->inclusive ? "]" : ")");
    else if (spec.min)
      range = (spec.min->inclusive ? ">= " : "> ") + format_number(spec.min->value);
    else
      range = (spec.max->inclusive ? "<= " : "< ") + format_number(spec.max->value);
    errors_.fail(&node, key, where + "must be " + range + ", got " + format_number(v));
  }

  void string_value(const toml::node& node, const KeySpec& spec, const std::string& key,
                    const std::string& where) const {
    const std::string text = node.value<std::string>().value_or("");
    if (!spec.allowed.empty() &&
        std::find(spec.allowed.begin(), spec.allowed.end(), text) == spec.allowed.end())
      errors_.fail(&node, key,
                   where + "must be " + quoted_list(spec.allowed) + ", got '" + text + "'" +
                       did_you_mean(text, spec.allowed));
    if (!matches_format(text, spec.format))
      errors_.fail(&node, key,
                   where + "must be an identifier (letters, digits, '_'" +
                       (spec.format == StringFormat::Name ? ", '-'" : "") +
                       "; not starting with a digit), got '" + text + "'");
  }

  const SceneSchema& schema_;
  const ErrorContext& errors_;
  int dimension_;
  std::vector<std::string> phases_;
};

}  // namespace

int validate_against_schema(toml::table& root, const SceneSchema& schema,
                            const ErrorContext& errors) {
  // The dimension decides every vector length, so it is checked before anything else.
  int dimension = 2;
  if (const toml::node* node = root["run"]["dimension"].node()) {
    Validator(schema, errors, dimension)
        .value(*node, *schema.find_key("run.dimension"), "run.dimension");
    dimension = static_cast<int>(*node->value<int64_t>());
  }
  Validator(schema, errors, dimension, phases_in(root)).table(root, "", "");
  return dimension;
}

namespace {

void promote_node(toml::node& node, ValueType type) {
  if (type == ValueType::VectorList) {
    for (auto& entry : *node.as_array()) promote_node(entry, ValueType::Vector);
    return;
  }
  if (type != ValueType::Vector) return;
  toml::array& array = *node.as_array();
  for (std::size_t i = 0; i < array.size(); ++i)
    if (array.get(i)->is_integer())
      array.replace(array.cbegin() + i, *array.get(i)->value<double>());
}

void promote_table(toml::table& table, const SceneSchema& schema, const std::string& schema_path) {
  for (auto& [name, node] : table) {
    const std::string path = join_key(schema_path, std::string(name.str()));
    if (node.is_table()) {
      promote_table(*node.as_table(), schema, path);
    } else if (schema.find_table(path + "[]")) {
      for (auto& element : *node.as_array())
        promote_table(*element.as_table(), schema, path + "[]");
    } else if (const KeySpec* spec = schema.find_key(path)) {
      if (spec->type == ValueType::Float && node.is_integer())
        table.insert_or_assign(name, *node.value<double>());
      else
        promote_node(node, spec->type);
    }
  }
}

}  // namespace

void promote_integers(toml::table& root, const SceneSchema& schema) {
  promote_table(root, schema, "");
}

}  // namespace porosph::scene
