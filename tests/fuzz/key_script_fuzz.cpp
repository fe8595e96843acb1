// libFuzzer target for the key-script reader: any bytes are a key script. InputError is the reader
// refusing bad input; any other exception escapes and counts as a crash. An accepted script must
// keep key_script.hpp's promises: finite times from 0, never decreasing, key codes 0..65535.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "gizmo/io/diagnostics.hpp"
#include "gizmo/io/key_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::vector<gizmo::io::KeyInput> keys =
        gizmo::io::readKeyScript(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.keys");
    double last = 0;
    for (const gizmo::io::KeyInput& k : keys) {
      if (!std::isfinite(k.time) || k.time < last || k.key < 0 || k.key > 65535) {
        std::fprintf(stderr, "broken promise: accepted key input at line %d: time %a key %d\n", k.where.line, k.time,
                     k.key);
        std::abort();
      }
      last = k.time;
    }
  } catch (const gizmo::io::InputError&) {}
  return 0;
}
