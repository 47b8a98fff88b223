// The fuzz target's entry function, shared by the libFuzzer binary (fuzz_geo)
// and the corpus/regression replay test (fuzz_corpus_replay, any compiler).
#pragma once

#include <cstddef>
#include <cstdint>

namespace sm::fuzz {

/// Lexes and parses one input as a .geo script, checks the front end's
/// invariants (aborting on a violation, so the fuzzer reports it), then hands
/// syntactically valid input to evaluate_parsed(). Never throws.
void run_geo_input(const std::uint8_t* data, std::size_t size);

}  // namespace sm::fuzz
