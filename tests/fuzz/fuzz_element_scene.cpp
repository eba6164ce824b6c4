// Element-test scenes (acst_element): driver::parse_scene on the fuzzer's bytes. Relative file
// names resolve against data/scenes/element, where the bundled scenes of the corpus live.
#include "acst_driver/scene.hpp"
#include "reader_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  return acst::fuzz::read_or_refuse(data, size, [](const std::string& text) {
    acst::driver::parse_scene(text, ACST_DATA_DIR "/scenes/element", "fuzz");
  });
}
