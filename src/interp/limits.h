// Hard limits that keep hostile scripts from hanging or exhausting memory;
// each one is reported with a clear message when hit.
#pragma once

#include <cstddef>
#include <cstdint>

namespace sm::interp {

/// Largest list a range, LinSpace, ListFromFile or list growth may build.
inline constexpr std::size_t kMaxListSize = 100'000'000;
/// Longest string a script may build (StrCat, Sprintf, StrReplace...).
inline constexpr std::size_t kMaxStringSize = 64u << 20;
/// Statements and loop iterations executed by one run before it is stopped as a
/// runaway loop (about 4 s of evaluation; real scripts stay far below).
inline constexpr std::uint64_t kMaxStatements = 100'000'000;
/// Nested Call/Include frames (recursive macros).
inline constexpr std::size_t kMaxCallDepth = 200;
/// Nested evaluation (expressions within statements within blocks within
/// macro calls); keeps the evaluator's recursion far below an 8 MiB stack.
inline constexpr std::size_t kMaxEvalDepth = 4000;
/// Nested Include files.
inline constexpr std::size_t kMaxIncludeDepth = 64;

/// The limits of one run. The defaults are the constants above; tests and
/// the fuzzer pass smaller ones (RunSettings::limits) to stay fast.
struct Limits {
  std::size_t max_list_size = kMaxListSize;
  std::size_t max_string_size = kMaxStringSize;
  std::uint64_t max_statements = kMaxStatements;
  std::size_t max_call_depth = kMaxCallDepth;
  std::size_t max_include_depth = kMaxIncludeDepth;
  std::size_t max_eval_depth = kMaxEvalDepth;
};

}  // namespace sm::interp
