#include "scene/term_registry.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace porosph::scene {
namespace {

bool has_phase(const Scene& scene, const std::string& phase) {
  if (phase == "water") return scene.water.has_value();
  if (phase == "soil") return scene.soil.has_value();
  if (phase == "interaction") return scene.water.has_value() && scene.soil.has_value();
  throw std::logic_error("term registry: unknown phase '" + phase + "'");
}

std::string cell(std::string text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::vector<TermSpec> make_term_registry() {
  std::vector<TermSpec> terms;
  term_detail::add_water_terms(terms);
  term_detail::add_soil_terms(terms);
  term_detail::add_interaction_terms(terms);
  return terms;
}

std::vector<std::string> active_terms(const Scene& scene, const std::string& phase) {
  std::vector<std::string> names;
  if (!has_phase(scene, phase)) return names;
  for (const TermSpec& term : make_term_registry())
    if (term.phase == phase && term.active(scene)) names.push_back(term.name);
  return names;
}

TermSwitches::TermSwitches(const Scene& scene, std::string phase) : phase_(std::move(phase)) {
  const bool present = has_phase(scene, phase_);  // also refuses an unknown phase
  for (const TermSpec& term : make_term_registry()) {
    if (term.phase != phase_) continue;
    known_.push_back(term.name);
    if (present && term.active(scene)) active_.push_back(term.name);
  }
}

bool TermSwitches::operator()(const std::string& name) const {
  if (std::find(known_.begin(), known_.end(), name) == known_.end())
    throw std::logic_error("term registry: no " + phase_ + " term named '" + name + "'");
  return std::find(active_.begin(), active_.end(), name) != active_.end();
}

void add_term_keys(SceneSchema& schema) {
  for (const TermSpec& term : make_term_registry()) {
    for (const KeySpec& key : term.keys) {
      const std::string table = key.table();
      auto last = schema.keys.end();
      for (auto it = schema.keys.begin(); it != schema.keys.end(); ++it)
        if (it->table() == table) last = it + 1;
      if (schema.find_table(table) == nullptr)
        throw std::logic_error("term " + term.name + ": key " + key.path + " in no table");
      schema.keys.insert(last, key);
    }
  }
  for (const TermSpec& term : make_term_registry()) {
    if (!term.choice) continue;
    const auto key = std::find_if(schema.keys.begin(), schema.keys.end(),
                                  [&](const KeySpec& k) { return k.path == term.choice->key; });
    if (key == schema.keys.end() || key->type != ValueType::String)
      throw std::logic_error("term " + term.name + ": its choice key " + term.choice->key +
                             " is no string key of a registered term");
    key->allowed.push_back(term.choice->value);
  }
}

std::string term_reference_markdown() {
  std::ostringstream md;
  md << "# Physics terms\n\n"
     << "<!-- Generated from scene/terms_*.cpp by `build/bin/coupler schema --terms > "
        "docs/terms.md`; do not edit by hand. -->\n\n"
     << "Every term a built-in solver evaluates, registered once (scene/term_registry.h): what "
        "switches it on and the scene keys it owns (docs/scene.md has their types, defaults "
        "and ranges). `coupler check` prints the terms a scene switches on, and run.json lists "
        "them under `phases.<phase>.terms` (the coupler's exchange under `interaction.terms`). "
        "A term that is off is not evaluated.\n";
  for (const std::string phase : {"water", "soil", "interaction"}) {
    md << "\n## " << phase << "\n\n| Term | Runs when | Keys | What it is |\n"
       << "|------|-----------|------|------------|\n";
    for (const TermSpec& term : make_term_registry()) {
      if (term.phase != phase) continue;
      std::string keys;
      for (const KeySpec& key : term.keys) keys += (keys.empty() ? "`" : ", `") + key.path + "`";
      md << "| `" << term.name << "` | " << cell(term.runs_when) << " | "
         << (keys.empty() ? "-" : cell(keys)) << " | " << cell(term.summary) << " |\n";
    }
  }
  return md.str();
}

}  // namespace porosph::scene
