// Loads an SDF world with libsdformat (the parser gz-sim uses) and prints what it holds;
// built by tests/backends/test_gazebo.py when Debian's libsdformat-dev is installed.
#include <sdf/sdf.hh>
#include <iostream>
int main(int argc, char** argv) {
  if (argc < 2) { std::cerr << "usage: check WORLD.sdf\n"; return 2; }
  sdf::Root root;
  sdf::Errors errors = root.Load(argv[1]);
  for (const auto& e : errors) std::cout << "error: " << e.Message() << "\n";
  if (!errors.empty()) return 1;
  for (uint64_t w = 0; w < root.WorldCount(); ++w) {
    const sdf::World* world = root.WorldByIndex(w);
    std::cout << "world " << world->Name() << " models " << world->ModelCount()
              << " lights " << world->LightCount() << " frames " << world->FrameCount() << "\n";
    for (uint64_t m = 0; m < world->ModelCount(); ++m) {
      const sdf::Model* model = world->ModelByIndex(m);
      std::cout << "model " << model->Name() << " links " << model->LinkCount();
      uint64_t visuals = 0;
      for (uint64_t l = 0; l < model->LinkCount(); ++l) visuals += model->LinkByIndex(l)->VisualCount();
      std::cout << " visuals " << visuals << "\n";
    }
  }
  return 0;
}
