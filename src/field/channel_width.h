// ChannelWidth field: the local width of the water (the diameter of the largest
// empty ball touching the coast, the medial-axis idea behind OceanMesh2D's feature
// size) divided by ElementsAcross, so that every channel gets that many elements.
#pragma once

#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "base/vec.h"
#include "field/coast_chain.h"
#include "field/registry.h"

namespace sm::field {

struct ChannelWidthOptions {
  double elements_across = 2;  ///< N: elements across a channel (>= 1)
  double size_min = 0;         ///< the size never goes below this
  double size_max = kMaxLc;    ///< nor above this; widths beyond N * size_max are not searched
  /// Threads for the set-up's searches (General.NumThreads; <= 0: the hardware's). The
  /// widths are the same for any count.
  int threads = 1;
};

/// The per-sample widths and the evaluation, exposed for tests.
class ChannelWidths {
 public:
  /// `cap`: widths larger than this are not searched for and read as `cap`. The samples'
  /// searches run on `threads` threads (<= 0: the hardware's); the widths do not depend on it.
  /// `seeded`: each search starts from the points that set the previous sample's widths
  /// (the same widths, sooner; false only for tests and measurements of the unseeded one).
  ChannelWidths(std::vector<CoastChain> chains, double cap, int threads = 1, bool seeded = true);
  ~ChannelWidths();
  ChannelWidths(const ChannelWidths&) = delete;
  ChannelWidths& operator=(const ChannelWidths&) = delete;

  /// Local width of the water at each point: the width at the nearest coast
  /// sample, on the side of the coast the point lies on (both sides' smaller
  /// one for points on the coast), interpolated along the coast; at least twice
  /// the distance to the coast, at most the cap.
  void width(std::span<const Vec3> pts, std::span<double> w) const;
  /// The same where the width is below max_width[i] (one value for all points, or
  /// one per point); elsewhere some value at least that.
  void width_within(std::span<const Vec3> pts, std::span<const double> max_width, std::span<double> w) const;
  /// True only where width_within(x, max_width) is certainly at least min(max_width,
  /// the cap), known from a grid of the samples' smallest widths without a search
  /// (false where the grid cannot tell).
  bool certainly_at_least(const Vec3& x, double max_width) const;
  std::size_t samples() const;
  /// Sample i's widths on its +side and -side (the chains' samples in order, empty
  /// chains skipped), for tests against a brute force.
  std::pair<double, double> sample_widths(std::size_t i) const;

 private:
  // The evaluations run in pieces (field/batch_pieces.h), their scratch on the stack.
  void width_piece(std::span<const Vec3> pts, std::span<const double> max_width, std::span<double> w) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The field: clamp(width / ElementsAcross, SizeMin, SizeMax); no constraint
/// (SizeMax) where the width reaches the search cap.
class ChannelWidthField final : public SizeField {
 public:
  ChannelWidthField(std::vector<CoastChain> chains, const ChannelWidthOptions& o, double cap);
  void eval(std::span<const Vec3> pts, std::span<double> h) const override;
  /// h[i] = min(h[i], the field at pts[i]), with the coast searched only as far as
  /// could still lower h[i]: cheap where h is already small (Mesh.ElementsAcrossChannels
  /// inside the Min of the background field).
  void lower(std::span<const Vec3> pts, std::span<double> h) const;

 private:
  void lower_piece(std::span<const Vec3> pts, std::span<double> h) const;
  double size_of(double width) const;
  ChannelWidths widths_;
  ChannelWidthOptions o_;
  double cap_;
};

/// Direct construction (Mesh.ElementsAcrossChannels, tests, benchmarks).
/// Throws BadValue on a non-finite sample or an option out of range.
std::shared_ptr<const ChannelWidthField> make_channel_width_field(std::vector<CoastChain> chains,
                                                                  const ChannelWidthOptions& opts);

}  // namespace sm::field
