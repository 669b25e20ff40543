// Fuzz target: the scene-file loader and the parameter parser (app/runner/scene_file.h, app/runner/params.h) over
// the hello lab's scenes. Besides no sanitizer report: an error is one line naming the file; a file
// that loads saves to JSON that loads again to the same JSON (round trip, docs/architecture.md §4);
// any text given to any parameter is accepted or refused with one line naming the parameter.
#include <cstdint>
#include <string>

#include "app/runner/scene_file.h"
#include "fuzz_check.h"

using namespace pba;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Result<app::LoadedScene> loaded = app::parseSceneJson(text, "fuzz.json", "hello");
  if (!loaded) {
    fuzz::requireOneLineNaming(loaded.error(), "fuzz.json: ");
  } else {
    app::LoadedScene& s = loaded.value();
    const nlohmann::json saved = app::sceneToJson("hello", s.name, *s.scene, s.dt);
    Result<app::LoadedScene> again = app::parseSceneJson(saved.dump(2), "saved.json", "hello");
    fuzz::require(again.ok(), "a saved scene loads again", again.ok() ? "" : again.error());
    fuzz::require(app::sceneToJson("hello", again.value().name, *again.value().scene, again.value().dt) == saved,
                  "load -> save -> load is exact", saved.dump());
  }
  // The first line of the input as a command-line value of every parameter of the drop scene.
  Result<app::LoadedScene> drop = app::parseSceneJson(R"({"lab": "hello", "scene": "drop"})", "drop.json", "hello");
  const std::string value = text.substr(0, text.find('\n'));
  for (const app::Param& p : drop.value().scene->params().all()) {
    const Status st = drop.value().scene->params().setFromText(p.name, value);
    if (!st) fuzz::requireOneLineNaming(st.error(), p.name + ": ");
  }
  return 0;
}
