// Reading a scene: TOML text -> overrides -> schema validation -> consistency checks -> Scene.
#include "scene/scene_loader.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "scene/scene_internal.h"
#include "scene/scene_sanity.h"

namespace porosph::scene {
namespace {

/// True if the text so far ends (spaces aside) where a TOML value starts: after '=', ',' or '['.
bool at_value_start(const std::string& text) {
  const auto last = text.find_last_not_of(" \t\n");
  return last != std::string::npos && (text[last] == '=' || text[last] == ',' || text[last] == '[');
}

/// toml++ prints floats with 17 significant digits (0.1 -> 0.10000000000000001). Rewrites every
/// float outside strings in its shortest form that reads back as the same double, so the resolved
/// scene is readable and still exact.
std::string shorten_floats(const std::string& toml_text) {
  std::string out;
  out.reserve(toml_text.size());
  char quote = 0;  // the quote character while inside a string
  for (std::size_t i = 0; i < toml_text.size(); ++i) {
    const char c = toml_text[i];
    if (quote) {
      out += c;
      if (quote == '"' && c == '\\' && i + 1 < toml_text.size())
        out += toml_text[++i];
      else if (c == quote)
        quote = 0;
      continue;
    }
    if (c == '\'' || c == '"') quote = c;
    const bool number_start = std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+';
    if (!number_start || !at_value_start(out)) {
      out += c;
      continue;
    }
    const auto end = toml_text.find_first_not_of("0123456789+-.eE_", i);
    const std::string token = toml_text.substr(i, end - i);
    i = (end == std::string::npos ? toml_text.size() : end) - 1;
    if (token.find_first_of(".eE") == std::string::npos || token.find('_') != std::string::npos) {
      out += token;  // an integer (or a form we leave alone)
      continue;
    }
    std::string shortest = format_number(std::strtod(token.c_str(), nullptr));
    if (shortest.find_first_of(".e") == std::string::npos) shortest += ".0";
    out += shortest;
  }
  return out;
}

}  // namespace

Scene load_scene_text(const std::string& text, const std::string& source_name,
                      const std::vector<std::string>& overrides) {
  const std::string file = source_name.empty() ? std::string("<scene>") : source_name;
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw SceneError(file, static_cast<int>(e.source().begin.line), "",
                     "TOML syntax error: " + std::string(e.description()));
  }
  const SceneSchema schema = make_scene_schema();
  apply_overrides(root, overrides, schema);
  const ErrorContext errors(file);
  const int dimension = validate_against_schema(root, schema, errors);
  check_scene_consistency(root, dimension, errors);

  Scene scene = build_scene(root);
  check_scene_sanity(root, scene, errors);
  scene.source_path = source_name;
  promote_integers(root, schema);
  std::ostringstream resolved;
  resolved << toml::toml_formatter(root) << "\n";
  scene.resolved_toml = shorten_floats(resolved.str());
  return scene;
}

Scene load_scene_file(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw SceneError(path, 0, "",
                     std::string("cannot open the scene file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return load_scene_text(text.str(), path, overrides);
}

}  // namespace porosph::scene
