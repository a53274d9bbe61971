// Reading a scene: TOML text -> overrides applied -> every key validated -> typed Scene.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace porosph::scene {

/// A scene that cannot be used. what() reads "FILE:LINE: key 'a.b': message" so a user finds the
/// spot at once; line is 0 when the problem is a missing key (then the file is named alone) and
/// file is "--set" for a bad command-line override.
class SceneError : public std::runtime_error {
 public:
  SceneError(std::string file, int line, std::string key, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }

 private:
  std::string file_;
  int line_;
  std::string key_;
};

/// Reads, overrides (`a.b=value`, value in TOML syntax; a bare word is taken as a string) and
/// validates a scene file. Throws SceneError.
Scene load_scene_file(const std::string& path, const std::vector<std::string>& overrides = {});

/// Same for scene text held in memory; `source_name` stands for the file name in errors.
Scene load_scene_text(const std::string& text, const std::string& source_name,
                      const std::vector<std::string>& overrides = {});

/// Markdown reference of every scene key (name, type, unit, default, range, description):
/// the content of docs/scene.md.
std::string scene_reference_markdown();

}  // namespace porosph::scene
