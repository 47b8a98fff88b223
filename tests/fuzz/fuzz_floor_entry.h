// Entry function of the quality-floor fuzz target (fuzz_floor_entry.cpp has the input
// layout), shared by the libFuzzer binary fuzz_floor and the replay test
// fuzz_replay_floor (any compiler).
#pragma once

#include <cstddef>
#include <cstdint>

namespace sm::fuzz {

/// A random plane coast (star-shaped outer loop, islands) meshed with a random quality
/// floor; aborts on an invalid mesh, an internal error or an unreported bad triangle.
void run_floor_input(const std::uint8_t* data, std::size_t size);

}  // namespace sm::fuzz
