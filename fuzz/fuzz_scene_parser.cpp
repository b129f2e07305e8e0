// libFuzzer target: any bytes as a scene. The parser must never crash, hang or allocate without
// bound; when it accepts, every promise of fuzz/scene_checks.h must hold.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/scene_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  check_scene_text(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
