// The physics terms of every phase, each registered once (issue 24; docs/contributing.md).
//
// A registration says what the term is (its name as run.json's phases.<phase>.terms lists it,
// its equation and source, the file that codes it), which scene keys it owns (type, default,
// unit, doc: declared here and nowhere else) and the predicate that switches it on. From it:
// - make_scene_schema() takes the term keys, so docs/scene.md and the loader's checks follow;
// - the built-in solvers take their switches (TermSwitches): a term the registry leaves off is
//   not evaluated, and the solver's run.json list is the registry's;
// - `coupler check` prints the terms each phase will evaluate, `coupler schema --markdown`
//   documents them (docs/terms.md).
// Registrations live by phase in terms_water.cpp and terms_soil.cpp (soil and interaction).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_schema.h"

namespace porosph::scene {

/// "This term is one value of a string key" (the laws of a family, e.g. the laminar viscosity
/// laws of water.laminar_viscosity): the value joins the key's allowed values (add_term_keys).
struct TermChoice {
  std::string key;    ///< dotted path of a String key some term owns
  std::string value;  ///< the value that selects this term
};

/// One physics term.
struct TermSpec {
  std::string name;           ///< as listed in run.json phases.<phase>.terms, unique per phase
  std::string phase;          ///< "water", "soil" or "interaction" (the coupler's exchange)
  std::string summary;        ///< what it is: equation, source, the file that codes it
  std::string runs_when;      ///< the switch in words ("always", "water.viscosity > 0", ...)
  std::vector<KeySpec> keys;  ///< the scene keys the term owns
  std::function<bool(const Scene&)> active;  ///< the switch itself
  std::optional<TermChoice> choice;          ///< set for one law of a family
};

/// Every term of every phase, in documentation order.
std::vector<TermSpec> make_term_registry();

/// Names of the terms of `phase` that `scene` switches on, in registry order; empty when the
/// scene lacks the phase (for "interaction": water or soil).
std::vector<std::string> active_terms(const Scene& scene, const std::string& phase);

/// The switches of one phase for one scene, read by name. Asking for a name the registry does
/// not hold for the phase throws std::logic_error (a misspelt switch is a defect, not "off").
class TermSwitches {
 public:
  TermSwitches(const Scene& scene, std::string phase);
  bool operator()(const std::string& name) const;
  const std::vector<std::string>& active() const { return active_; }

 private:
  std::string phase_;
  std::vector<std::string> known_;
  std::vector<std::string> active_;
};

/// Adds the keys of every registered term to `schema`, each after the last key of its table, and
/// each term's TermChoice value to its key's allowed values (registry order).
void add_term_keys(SceneSchema& schema);

/// docs/terms.md: each phase's terms, what switches them and the keys they own.
std::string term_reference_markdown();

namespace term_detail {
/// Whether any run.periodic axis is set (terms of every phase ask).
bool any_periodic(const Scene& s);
/// Water terms (terms_water.cpp).
void add_water_terms(std::vector<TermSpec>& terms);
/// Soil terms and the soil-water interaction's (terms_soil.cpp).
void add_soil_terms(std::vector<TermSpec>& terms);
void add_interaction_terms(std::vector<TermSpec>& terms);
}  // namespace term_detail

}  // namespace porosph::scene
