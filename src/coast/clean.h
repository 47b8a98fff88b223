// Cleaning of raw shoreline rings before coarsening (the artefacts the real
// files hold, data/PROVENANCE.md): consecutive duplicates, zero-width spikes a->b->a, degenerate rings, and
// vertices on the projection's singular point (the South Pole).
#pragma once

#include <string>
#include <vector>

#include "coast/coastline.h"

namespace sm::coast {

enum class CleanAction {
  Duplicate,      // consecutive copy of the previous vertex removed
  Spike,          // vertex b of a -> b -> a removed (with the second a)
  PoleVertex,     // vertex at lat -90 removed from a pole-closed ring (Natural Earth)
  DegenerateRing, // ring with fewer than 3 distinct vertices (or a polyline < 2) dropped
  MergedRings,    // two closed rings sharing an edge (a polygon split at the dateline) joined
};

struct CleanEntry {
  CleanAction action;
  std::size_t record;    // Ring::record
  std::int64_t id;       // Ring::id
  geo::LonLat where;     // the removed vertex, or the ring's first vertex
};

struct CleanReport {
  std::vector<CleanEntry> entries;
  std::size_t count(CleanAction a) const;
  std::string summary() const;   // one line: counts per action
};

/// Cleans every ring in place; dropped rings are erased. Deterministic (ring order kept),
/// the same for every number of `threads` (<= 0: the hardware concurrency).
CleanReport clean(Coastline& c, int threads = 1);

/// Joins closed rings of the same level that share an edge run in opposite directions
/// (shapefiles split polygons at the dateline: GSHHS_l_L1.shp, Natural Earth's Fiji and
/// Chukotka; touching islands in general). The merged ring replaces the first of the two;
/// the leftover shared run becomes spikes, which are removed. Appends to `rep`. The same
/// for every number of `threads`.
void merge_touching_rings(Coastline& c, CleanReport& rep, int threads = 1);

}  // namespace sm::coast
