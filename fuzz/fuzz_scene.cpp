// libFuzzer target: a `frustum render` scene file from arbitrary bytes (objects, meshes,
// nested children with `repeat`) is read with the scene reader. It either fails with a
// located message or gives a scene within the limits: the triangle count, repeats included,
// at most kMaxSceneTriangles, and at most kMaxScenePixels pixels.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "solver/input/given_reader.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/shared/scene_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const frustum::YamlDocument doc = frustum::parse_yaml(text, "scene.yaml");
  if (doc.error || !doc.root.IsMap()) return 0;
  try {
    frustum::GivenReader root(doc.root, "scene.yaml", "", {"title", "conventions", "scene"});
    const frustum::Conventions c =
        frustum::read_conventions(doc.root["conventions"], "scene.yaml", "conventions", {});
    frustum::GivenReader s = root.child("scene", frustum::scene_fields());
    const frustum::SceneSpec spec = frustum::read_scene(s, c);
    if (spec.triangles < 0 || spec.triangles > frustum::kMaxSceneTriangles) std::abort();
    if (static_cast<long>(spec.scene.width) * spec.scene.height > frustum::kMaxScenePixels)
      std::abort();
  } catch (const frustum::InputError& e) {
    if (e.diagnostic().where.file != "scene.yaml") std::abort();
  } catch (const frustum::DomainError&) {
  }
  return 0;
}
