// What the 2D seepage checks (seepage_weir_check, seepage_embankment_check) read from a run the
// same way: boxes from the resolved scene, the first soil material's conductivity and the still
// water the pool heads are measured against, the water fields of a snapshot and the top of a
// pool's water.
#pragma once

#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/snapshot_reader.h"
#include "tools/validation/still_water.h"

namespace porosph::validation {

/// An axis-aligned box of the plane.
struct SeepageBox {
  double x0, y0, x1, y1;
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

/// The min/max box of a scene entry of the given shape; errors name `check` and `what`.
inline SeepageBox seepage_box(const nlohmann::json& entry, const std::string& check,
                              const std::string& what, const std::string& shape = "box") {
  if (entry.at("shape").get<std::string>() != shape)
    throw std::runtime_error(check + ": " + what + " must be a " + shape);
  const auto lo = entry.at("min").get<std::vector<double>>();
  const auto hi = entry.at("max").get<std::vector<double>>();
  if (lo.size() != 2) throw std::runtime_error(check + ": a 2D scene is needed");
  return {lo[0], lo[1], hi[0], hi[1]};
}

/// The run's dp, the first soil material's K (darcy_conductivity required) and its still water
/// (gravity along -y required).
struct SeepageScene {
  double dp = 0.0, conductivity = 0.0;
  StillWater water;
};

inline SeepageScene seepage_scene(const nlohmann::json& parameters, const std::string& check,
                                  const std::string& soil) {
  const auto& material = parameters.at("soil").at("materials").at(0);
  if (material.at("seepage").get<std::string>() != "darcy_conductivity")
    throw std::runtime_error(check + ": the " + soil + "'s seepage must be darcy_conductivity");
  const auto gravity = parameters.at("run").at("gravity").get<std::vector<double>>();
  if (gravity.size() != 2 || gravity[0] != 0.0 || !(gravity[1] < 0.0))
    throw std::runtime_error(check + ": gravity must point along -y");
  const auto& w = parameters.at("water");
  return {parameters.at("run").at("dp").get<double>(),
          material.at("hydraulic_conductivity").get<double>(),
          StillWater{w.at("rho0").get<double>(), w.at("sound_speed").get<double>(),
                     w.at("gamma").get<double>(), -gravity[1]}};
}

/// The water fields of one snapshot of water.h5 (2D, row-major).
struct WaterSnapshot {
  io::FieldData<double> x, v, p, rho, m;
  io::FieldData<std::uint8_t> fixed;
  std::size_t rows() const { return x.rows; }
  bool free(std::size_t i) const { return fixed.values[i] == 0; }
  double px(std::size_t i) const { return x.values[2 * i]; }
  double py(std::size_t i) const { return x.values[2 * i + 1]; }
  double volume(std::size_t i) const { return m.values[i] / rho.values[i]; }
};

inline WaterSnapshot read_water_snapshot(const io::SnapshotReader& reader, std::uint32_t index) {
  return {reader.read_f64(index, "position"), reader.read_f64(index, "velocity"),
          reader.read_f64(index, "pressure"), reader.read_f64(index, "density"),
          reader.read_f64(index, "mass"),     reader.read_u8(index, "fixed")};
}

/// The highest free water particle's y inside `box` (-1e9 when there is none).
inline double highest_free_y(const WaterSnapshot& s, const SeepageBox& box) {
  double top = -1e9;
  for (std::size_t i = 0; i < s.rows(); ++i)
    if (s.free(i) && box.contains(s.px(i), s.py(i))) top = std::max(top, s.py(i));
  return top;
}

}  // namespace porosph::validation
