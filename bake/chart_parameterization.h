// The wavelet domain's parameterization (docs/ARCHITECTURE.md#wavelet-domain, after Hasan et al.
// 2006): N = M x 2^n x 2^n surface samples go to M square charts, and within a chart to the cells
// of a 2^n x 2^n grid, so that samples near each other on the surface are near each other on the
// grid (which is what lets 2D wavelets compress the transfer).
//
// Charts: the samples are split by recursive median splits along the longest bounding-box
// axis; a group of m charts splits into floor(m/2) and ceil(m/2) charts with sample counts
// in that proportion, so any M works, not only powers of two.
//
// Within a chart, a balanced quadtree: a node of s x s cells splits its samples in half
// along their longest axis (one grid axis), then each half in half along its own longest
// axis (the other grid axis). Which grid axis and which direction a spatial split takes
// follows an orientation frame (the 3D directions +u and +v point along, starting from the
// chart's two longest bounding-box axes), inherited from the parent and updated with the
// direction between the centroids of each split's halves, so quadrants keep a consistent
// orientation as the surface turns and cells on either side of a split stay grid
// neighbours. A half that splits along the same axis as its parent (a strip) is laid out
// as a snake, keeping the quarters next to the split plane side by side. All splits are
// exact medians (std::nth_element, ties broken by sample index): every cell gets exactly
// one sample and the result is deterministic.
#pragma once

#include "schema/wavelet/chart_layout.h"

#include <Imath/ImathVec.h>

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

// Returns the grid order: entry `cell` is the index of the sample that goes there, with
// cell = chart * size^2 + v * size + u (schema/wavelet/chart_layout.h). Throws opal::Error
// when positions.size() != layout.cells().
std::vector<std::uint32_t> parameterizeCharts(std::span<const Imath::V3f> positions, const ChartLayout& layout);

}  // namespace opal
