// The body of the scene fuzzer (fuzz/fuzz_main.cpp) and of its regression test
// (fuzz/tst_fuzz_regressions.cpp, over tests/fuzz_regressions/): one function, so an
// input that once crashed the fuzzer is replayed by exactly the same code in the
// normal build. docs/reliability.md, "Fuzzing".
#pragma once

#include <cstddef>
#include <cstdint>

namespace rbw::fuzz {

// At most this many steps are taken, whatever the scene's "steps" says.
inline constexpr long kMaxSteps = 4;

// Parses the bytes as a scene file with the real loader (parseScene) and, if they
// load, runs the scene for up to kMaxSteps steps twice, as `rbw run` does
// (app/cli/main.cpp): as JSON (traced steps, JsonRunWriter with the last trace, or the
// blow-up report) and as CSV (untraced steps, World::checkOutputs, CsvWriter). Returns 0.
// A broken invariant aborts, so the fuzzer reports it as a crash: a refused file
// without a message or whose message does not name the file, a loaded scene that
// validate() refuses, a blow-up without a message, a JSON document that is not one
// object; so do the sanitizers and the assertions (World asserts a valid scene).
// It also aborts on a NaN or an infinity in what the run prints: the result, the last
// trace, the blow-up report, the CSV rows (README: "No NaN is ever printed as a
// result"); RBW_FUZZ_CHECK_FINITE=0 turns that check off.
// The loader gets a '\0'-terminated copy of the bytes, as from QFile::readAll(); with
// RBW_FUZZ_RAW_BYTES=1 it gets them unterminated (QByteArray::fromRawData), which
// checks that it reads nothing past QByteArray::size().
int fuzzOneScene(const std::uint8_t* data, std::size_t size);

} // namespace rbw::fuzz
