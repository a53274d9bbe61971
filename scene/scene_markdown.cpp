// Renders the scene schema as the Markdown reference docs/scene.md (one table per TOML table).
#include <sstream>

#include "scene/scene_internal.h"
#include "scene/scene_loader.h"

namespace porosph::scene {
namespace {

std::string cell(std::string text) {
  std::string out;
  for (char c : text) out += (c == '|') ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string code_list(const std::vector<std::string>& values, const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i)
    out += (i == 0 ? "" : separator) + "`" + values[i] + "`";
  return out;
}

std::string type_text(const KeySpec& key) {
  const std::string length =
      key.vector_length > 0 ? std::to_string(key.vector_length) : std::string("dimension");
  switch (key.type) {
    case ValueType::Vector:
      return "float vector (" + length + ")";
    case ValueType::BoolVector:
      return "bool vector (" + length + ")";
    case ValueType::VectorList:
      return "list of float vectors (" + length + ")";
    default:
      return type_name(key.type);
  }
}

std::string default_text(const KeySpec& key) {
  const DefaultValue& d = key.default_value;
  switch (d.kind) {
    case DefaultValue::Kind::Required:
      return "required";
    case DefaultValue::Kind::Constant:
      return "`" + d.toml + "`";
    case DefaultValue::Kind::PerDimension:
      return "`" + d.toml_2d + "` (2D), `" + d.toml_3d + "` (3D)";
    case DefaultValue::Kind::Optional:
      return "optional";
    case DefaultValue::Kind::Derived:
      return d.rule;
  }
  return "";
}

std::string allowed_text(const KeySpec& key) {
  std::vector<std::string> parts;
  if (key.min && key.max) {
    parts.push_back(std::string(key.min->inclusive ? "[" : "(") + format_number(key.min->value) +
                    ", " + format_number(key.max->value) + (key.max->inclusive ? "]" : ")"));
  } else if (key.min) {
    parts.push_back((key.min->inclusive ? ">= " : "> ") + format_number(key.min->value));
  } else if (key.max) {
    parts.push_back((key.max->inclusive ? "<= " : "< ") + format_number(key.max->value));
  }
  if (!key.allowed.empty())
    parts.push_back((key.type == ValueType::StringList ? "each one of " : "") +
                    code_list(key.allowed, ", "));
  if (key.format == StringFormat::Identifier)
    parts.push_back("identifier `[A-Za-z_][A-Za-z0-9_]*`");
  if (key.format == StringFormat::Name) parts.push_back("name `[A-Za-z_][A-Za-z0-9_-]*`");
  if (key.min_count > 0)
    parts.push_back("at least " + std::to_string(key.min_count) +
                    (key.min_count == 1 ? " entry" : " entries"));
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i == 0 ? "" : "; ") + parts[i];
  return out;
}

std::string description_text(const KeySpec& key) {
  std::string out = key.description;
  if (key.applies_when)
    out += " Only when `" + key.applies_when->key + "` is " +
           code_list(key.applies_when->values, " or ") + ".";
  return out;
}

std::string table_heading(const TableSpec& table) {
  if (!table.array)
    return "## [" + table.header_name() + "]\n\n" +
           (table.required ? "Required table. " : "Optional table. ");
  return "## [[" + table.header_name() + "]]\n\n" +
         (table.required ? "Array of tables, at least one entry. "
                         : "Array of tables, optional, any number of entries. ");
}

}  // namespace

std::string scene_reference_markdown() {
  const SceneSchema schema = make_scene_schema();
  std::ostringstream md;
  md << "# Scene file reference\n\n"
     << "<!-- Generated from scene/scene_schema.cpp by `build/bin/coupler schema --markdown > "
        "docs/scene.md`; do not edit by hand. -->\n\n"
     << "A scene is a TOML file. All quantities are in SI units. A vector has `run.dimension` "
        "components; integers are accepted where floats are expected. Unknown keys, wrong types "
        "and out-of-range values are errors naming the file, line and key.\n\n"
     << "Any key can be overridden from the command line with `--set a.b=value`; the value is "
        "read as TOML (`0.005`, `[0.1, 0.2]`, `true`, `\"text\"`) and anything else as a bare "
        "string. Entries of an array of tables are addressed by their 0-based index, "
        "`walls[1].max` or `walls.1.max`.\n";
  for (const TableSpec& table : schema.tables) {
    md << "\n"
       << table_heading(table) << table.description << "\n\n"
       << "| Key | Type | Unit | Default | Allowed | Description |\n"
       << "|-----|------|------|---------|---------|-------------|\n";
    for (const KeySpec& key : schema.keys) {
      if (key.table() != table.path) continue;
      md << "| `" << key.name() << "` | " << cell(type_text(key)) << " | "
         << cell(key.unit.empty() ? "-" : key.unit) << " | " << cell(default_text(key)) << " | "
         << cell(allowed_text(key)) << " | " << cell(description_text(key)) << " |\n";
    }
  }
  return md.str();
}

}  // namespace porosph::scene
