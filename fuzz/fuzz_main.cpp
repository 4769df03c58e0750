// libFuzzer entry point of the scene fuzzer (built with clang, -DRBW_FUZZ=ON, preset
// "fuzz"). Everything it does is fuzzOneScene(), which the normal build's regression
// test (tst_fuzz_regressions) calls too. docs/reliability.md, "Fuzzing".
#include "fuzz/fuzz_scene.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    return rbw::fuzz::fuzzOneScene(data, size);
}
