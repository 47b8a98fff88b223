// A batch of size look-ups taken in pieces of at most kBatchPiece points whose scratch
// arrays live on the stack: the 2D refiners size about 15 points a call, and heap arrays
// made at every call cost more than their searches. Each point's answer depends on that
// point alone, so the pieces change no value. Used by the Threshold and ChannelWidth
// fields' lower() and ChannelWidths::width_within.
#pragma once

#include <algorithm>
#include <cstddef>

#include "base/vec.h"

namespace sm::field {

inline constexpr std::size_t kBatchPiece = 256;

/// Calls piece(from, count) for each piece [from, from + count) of a batch of n points.
template <class Piece>
void for_each_piece(std::size_t n, Piece&& piece) {
  for (std::size_t from = 0; from < n; from += kBatchPiece) piece(from, std::min(kBatchPiece, n - from));
}

/// kBatchPiece points on the stack, not initialised: an array of Vec3, whose members have
/// default values, would be written before use; the caller writes those it reads.
union PiecePoints {
  PiecePoints() {}
  Vec3 p[kBatchPiece];
};

}  // namespace sm::field
