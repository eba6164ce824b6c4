// MPM scenes (acst_mpm): mpm::parse_scene on the fuzzer's bytes, as if read from a file in
// data/scenes/mpm, where the bundled scenes of the corpus live (their parameter files resolve).
#include "acst_footing_tool/scene.hpp"
#include "reader_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  return acst::fuzz::read_or_refuse(data, size, [](const std::string& text) {
    acst::mpm::parse_scene(text, ACST_DATA_DIR "/scenes/mpm/fuzz.json");
  });
}
