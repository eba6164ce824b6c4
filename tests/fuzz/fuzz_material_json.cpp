// Material JSON (parameter sets, the material files of scenes and descriptions, the JSON of
// acst_model_create): the C++ reader (model_document, then the kind's own reader) and the C ABI
// on the same text. The C++ reader may refuse with the input-error type only; the ABI may only
// answer OK with a handle or ACST_INVALID_INPUT with a message and no handle, and the two must
// agree on whether the text is a material.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "acst.h"
#include "acst/json_input.hpp"

namespace {

[[noreturn]] void finding(const char* what, const acst_status& s) {
  std::fprintf(stderr, "fuzz_material_json: %s (code %d, message '%.256s')\n", what, s.code, s.message);
  std::abort();
}

// The C++ side of acst_model_create: true when the text is a material of one of the kinds.
bool cpp_accepts(const std::string& text) {
  try {
    const nlohmann::json doc = acst::model_document(text);
    const nlohmann::json model = doc.contains("model") ? doc["model"] : nlohmann::json("ACST");
    if (model == "linear_elastic") {
      acst::linear_elastic_from_json(doc["parameters"], "/parameters");
      return !doc.contains("integrator");
    }
    if (model == "von_mises") {
      acst::von_mises_from_json(doc["parameters"], "/parameters");
      return !doc.contains("integrator");
    }
    if (model == "drucker_prager") {
      acst::drucker_prager_from_json(doc["parameters"], "/parameters");
      return !doc.contains("integrator");
    }
    acst::material_from_document(doc);
    return true;
  } catch (const acst::common::InputError&) {
    return false;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  // acst_model_create reads a C string: the text up to the first NUL is what both sides see.
  const std::string text(reinterpret_cast<const char*>(data), strnlen(reinterpret_cast<const char*>(data), size));
  const bool accepted = cpp_accepts(text);

  acst_model* model = reinterpret_cast<acst_model*>(&model);  // not NULL: the call must reset it
  const acst_status s = acst_model_create(&model, text.c_str());
  if (std::memchr(s.message, '\0', sizeof s.message) == nullptr) finding("message not terminated", s);
  if (s.code == ACST_OK) {
    if (!model) finding("OK without a handle", s);
    if (s.message[0] != '\0') finding("OK with a message", s);
    const int n = acst_state_size(model);
    if (n != 0 && n != 1 && n != ACST_NSTATV) finding("state size not 0, 1 or ACST_NSTATV", s);
    for (int i = 0; i < n; ++i)
      if (!acst_state_name(model, i)) finding("state variable without a name", s);
    if (!acst_model_kind(model)) finding("handle without a kind", s);
  } else {
    if (s.code != ACST_INVALID_INPUT) finding("bad material JSON is not ACST_INVALID_INPUT", s);
    if (model) finding("a handle left after a failure", s);
    if (s.message[0] == '\0') finding("failure without a message", s);
  }
  if (accepted != (s.code == ACST_OK)) finding("the C++ reader and acst_model_create disagree", s);
  acst_model_destroy(s.code == ACST_OK ? model : nullptr);
  return 0;
}
